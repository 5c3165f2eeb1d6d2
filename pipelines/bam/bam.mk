# bam.mk -- the ballistic aggregation model against the inelastic gas in 2D (Fig. 10), included by
# Makefile.study.
#
#   make -f Makefile.study fig10 [SCALE=quick|default|paper]
#
# NRUN_BAM runs of the BAM (pipelines/scenes/fig10-bam-2d.ini) in a square of edge L_BAM to t_max =
# TMAX_BAM (the scale block of Makefile.study sets them and the fit windows BAM_ZETA_WIN and
# BAM_THETA_WIN). From them: the ensemble mean mass m(t) = N0/N(t) and E(t) per unit mass, each fitted
# with a power law (zeta_bam, theta_bam). Beside them the inelastic gas of Figs. 3 and 6: its cluster
# m(t) and E(t) and the fits those figures make (ZETA_e, THETA_e, no new run). The paper's
# hyperscaling relation 2 zeta + d theta = 2d (eq. 5; Trizac & Hansen 1995) is evaluated from both
# (pipelines/figures/fig10.sh; docs/PHYSICS.md "Ballistic aggregation").

BAM_ID     := L$(L_BAM)-t$(TMAX_BAM)
BAM_RUNIDS := $(shell seq 1 $(NRUN_BAM))
BAM_SIMD   := $(SIMD)/fig10/$(BAM_ID)
BAM_ANAD   := $(ANAD)/fig10/$(BAM_ID)
BAM_SIMS   := $(foreach k,$(BAM_RUNIDS),$(BAM_SIMD)/run$(k).h5)
BAM_MASS   := $(BAM_ANAD)/mass-R$(NRUN_BAM).h5
BAM_ENERGY := $(BAM_ANAD)/energy-R$(NRUN_BAM).h5
BAM_ZETA   := $(BAM_ANAD)/fits/zeta-R$(NRUN_BAM)-w$(call wtag,$(BAM_ZETA_WIN)).h5
BAM_THETA  := $(BAM_ANAD)/fits/theta-R$(NRUN_BAM)-w$(call wtag,$(BAM_THETA_WIN)).h5

$(BAM_SIMD)/run%.h5: $(SCENES)/fig10-bam-2d.ini | $(SIM)
	@mkdir -p $(@D)
	$(LAUNCH) $(SIM_RESUME) $(SIM) --scene $< --L $(L_BAM) --t-max $(TMAX_BAM) --seed $* --quiet \
	  --checkpoint-every $(CHECKPOINT_EVERY) -o $@
$(BAM_MASS): $(BAM_SIMS) | $(FIT)
	@mkdir -p $(@D)
	$(FIT) average --dataset /observables/mean_mass/value $^ -o $@
$(BAM_ENERGY): $(BAM_SIMS) | $(FIT)
	@mkdir -p $(@D)
	$(FIT) average --dataset /observables/kinetic_energy/value $^ -o $@
$(BAM_ZETA): $(BAM_MASS) | $(FIT)
	@mkdir -p $(@D)
	$(FIT) power-law $(FIT_OPTS) $<:/average/mean --window $(BAM_ZETA_WIN) -o $@
$(BAM_THETA): $(BAM_ENERGY) | $(FIT)
	@mkdir -p $(@D)
	$(FIT) power-law $(FIT_OPTS) $<:/average/mean --window $(BAM_THETA_WIN) -o $@

# The figure and its fits table: the BAM's four files, then per e of the inelastic gas its m(t), E(t)
# and their late fits (Figs. 3 and 6).
FIG10_IN := $(BAM_MASS) $(BAM_ENERGY) $(BAM_ZETA) $(BAM_THETA) \
            $(foreach e,$(ES),$(MASS_$(e)) $(ENERGY_$(e)) $(ZETA_$(e)) $(THETA_$(e)))
$(eval $(call STAMP_RULE,fig10,$(FIG10_IN)))
$(FIGURES)/fig10.png $(FIGURES)/fig10.svg $(FIGURES)/fig10.tsv $(FIGURES)/fig10.fits.tsv &: \
    $(FIG10_IN) $(FIGURES)/.fig10.inputs $(FIGSRC)/fig10.sh $(FIGSRC)/fig10.gp $(FIG_LIBS) | $(FIT)
	$(FIG_ENV) L_BAM=$(L_BAM) BAM_ZETA_WIN="$(BAM_ZETA_WIN)" BAM_THETA_WIN="$(BAM_THETA_WIN)" \
	  ZETA_WINS="$(foreach e,$(ES),$(call wtag,$(ZETA_WIN_$(e))))" \
	  THETA_WINS="$(foreach e,$(ES),$(call wtag,$(THETA_WIN_$(e))))" \
	  $(FIGSRC)/fig10.sh "$(BAM_MASS) $(BAM_ENERGY) $(BAM_ZETA) $(BAM_THETA)" "$(ES)" \
	  "$(foreach e,$(ES),$(MASS_$(e)))" "$(foreach e,$(ES),$(ENERGY_$(e)))" \
	  "$(foreach e,$(ES),$(ZETA_$(e)))" "$(foreach e,$(ES),$(THETA_$(e)))"
.PHONY: fig10
fig10: $(FIGURES)/fig10.png $(FIGURES)/fig10.svg $(FIGURES)/fig10.tsv $(FIGURES)/fig10.fits.tsv
sims: $(BAM_SIMS)
