# effect-driven.mk -- the driven gas reaching its steady state (pipelines/scenes/effect-driven.ini),
# one run per e in DRIVEN_ES, N = DRIVEN_N particles to t = DRIVEN_TMAX; the figure sets T(t) beside the
# steady temperature of the Enskog energy balance (pipelines/figures/effect-driven.sh).

DRIVEN_ES   ?= 0.5 0.8 0.95
DRIVEN_N    ?= 4000
DRIVEN_TMAX ?= 2000
DRIVEN_SIMD := $(SIMD)/effects/driven/N$(DRIVEN_N)-t$(DRIVEN_TMAX)
DRIVEN_SIMS := $(foreach e,$(DRIVEN_ES),$(DRIVEN_SIMD)/e$(e)/run1.h5)

# One launch path for every simulation (Makefile.study "simulations"): run<seed>.h5 under a folder
# per e, as the Slurm job arrays write them.
$(DRIVEN_SIMD)/e%/run1.h5: $(SCENES)/effect-driven.ini | $(SIM)
	@mkdir -p $(@D)
	$(LAUNCH) $(SIM_RESUME) $(SIM) --scene $< --N $(DRIVEN_N) --e $* --t-max $(DRIVEN_TMAX) --seed 1 --quiet \
	  --checkpoint-every $(CHECKPOINT_EVERY) -o $@

$(eval $(call STAMP_RULE,effect-driven,$(DRIVEN_SIMS)))
$(FIGURES)/effect-driven.png $(FIGURES)/effect-driven.svg $(FIGURES)/effect-driven.tsv \
  $(FIGURES)/effect-driven.fits.tsv &: $(DRIVEN_SIMS) $(FIGURES)/.effect-driven.inputs $(SCENES)/effect-driven.ini \
    $(FIGSRC)/effect-driven.sh $(FIGSRC)/effect-driven.gp $(FIG_LIBS) | $(FIT)
	$(FIG_ENV) $(FIGSRC)/effect-driven.sh "$(DRIVEN_ES)" "$(DRIVEN_SIMS)"
effects: $(FIGURES)/effect-driven.png
