# spheres.mk -- 3D cooling of inelastic hard spheres (Fig. 9), included by Makefile.study.
#
#   make -f Makefile.study fig9 [SCALE=quick|default|paper]
#
# NRUN3 runs per e = 0.5 and 0.9 in a cube of edge L3 at the packing fraction of the 2D study
# (pipelines/scenes/fig9-3d-e*.ini: rho = 0.55, eta = 0.288); the scale block of Makefile.study sets
# L3, NRUN3, TMAX3_e and the fit windows ZETA3_WIN_e, THETA3_WIN_e. Per e: the ensemble E(t) with
# Haff's law (gg-fit haff, t0 against the Enskog t0 with the Carnahan-Starling contact value) and a
# late power law t^-theta; the ensemble m(t) (gg-cluster in 3D) with a late power law and its local
# exponent, and the largest cluster. Clusters: the unit grid and 3x3x3 block of the 2D study, face
# connectivity (6), and the threshold RHO_C3 = 0.75, the 2D threshold's packing fraction
# (pi 0.5/4 = 0.393 = pi 0.75/6), so that 2D and 3D cut the same packing fraction at the same ratio to
# the mean (docs/PHYSICS.md "Hard spheres (3D)").

ES3          := 0.5 0.9
RHO_C3       ?= 0.75
CONNECTIVITY3 ?= 6
RUNIDS3      := $(shell seq 1 $(NRUN3))
GRID_OPTS3   := --grid $(GRID) --coarse $(COARSE) --rho-c $(RHO_C3)
CTAG3        := g$(GRID)w$(COARSE)rc$(RHO_C3)c$(CONNECTIVITY3)m$(MIN_SIZE)
ens3_id = e$(1)-L$(L3)-t$(TMAX3_$(1))

# One e: NRUN3 simulations (seed = run number), per-run clusters, ensemble averages and fits.
define SPHERES_ENSEMBLE
SIM3_DIR_$(1) := $(SIMD)/fig9/$(call ens3_id,$(1))
ANA3_DIR_$(1) := $(ANAD)/fig9/$(call ens3_id,$(1))
SIMS3_$(1)    := $(foreach k,$(RUNIDS3),$$(SIM3_DIR_$(1))/run$(k).h5)
CLUSTERS3_$(1):= $(foreach k,$(RUNIDS3),$$(ANA3_DIR_$(1))/run$(k).cluster-$(CTAG3).h5)
MASS3_$(1)    := $$(ANA3_DIR_$(1))/mass-$(CTAG3)-R$(NRUN3).h5
LARGEST3_$(1) := $$(ANA3_DIR_$(1))/largest-$(CTAG3)-R$(NRUN3).h5
ENERGY3_$(1)  := $$(ANA3_DIR_$(1))/energy-R$(NRUN3).h5
ZETA3_$(1)    := $$(ANA3_DIR_$(1))/fits/zeta-$(CTAG3)-R$(NRUN3)-w$(call wtag,$(ZETA3_WIN_$(1))).h5
ZETAL3_$(1)   := $$(ANA3_DIR_$(1))/fits/zeta-largest-$(CTAG3)-R$(NRUN3)-w$(call wtag,$(ZETA3_WIN_$(1))).h5
LOCAL3_$(1)   := $$(ANA3_DIR_$(1))/fits/local-$(CTAG3)-R$(NRUN3).h5
THETA3_$(1)   := $$(ANA3_DIR_$(1))/fits/theta-R$(NRUN3)-w$(call wtag,$(THETA3_WIN_$(1))).h5
HAFF3_$(1)    := $$(ANA3_DIR_$(1))/fits/haff-R$(NRUN3).h5

$$(SIM3_DIR_$(1))/run%.h5: $(SCENES)/fig9-3d-e$(1).ini | $(SIM)
	@mkdir -p $$(@D)
	$$(LAUNCH) $(SIM_RESUME) $(SIM) --scene $$< --L $(L3) --t-max $(TMAX3_$(1)) --seed $$* --quiet \
	  --checkpoint-every $$(CHECKPOINT_EVERY) -o $$@
$$(ANA3_DIR_$(1))/run%.cluster-$(CTAG3).h5: $$(SIM3_DIR_$(1))/run%.h5 | $(CLUSTER)
	@mkdir -p $$(@D)
	$(CLUSTER) --quiet $$< -o $$@ $(GRID_OPTS3) --connectivity $(CONNECTIVITY3) --min-size $(MIN_SIZE)
$$(MASS3_$(1)): $$(CLUSTERS3_$(1)) | $(FIT)
	$(FIT) average --dataset /cluster/mean_mass $$^ -o $$@
$$(LARGEST3_$(1)): $$(CLUSTERS3_$(1)) | $(FIT)
	$(FIT) average --dataset /cluster/largest $$^ -o $$@
$$(ENERGY3_$(1)): $$(SIMS3_$(1)) | $(FIT)
	@mkdir -p $$(@D)
	$(FIT) average --dataset /observables/kinetic_energy/value $$^ -o $$@
$$(ZETA3_$(1)): $$(MASS3_$(1)) | $(FIT)
	@mkdir -p $$(@D)
	$(FIT) power-law $(FIT_OPTS) $$<:/average/mean --window $(ZETA3_WIN_$(1)) -o $$@
$$(ZETAL3_$(1)): $$(LARGEST3_$(1)) | $(FIT)
	@mkdir -p $$(@D)
	$(FIT) power-law $(FIT_OPTS) $$<:/average/mean --window $(ZETA3_WIN_$(1)) -o $$@
$$(LOCAL3_$(1)): $$(MASS3_$(1)) | $(FIT)
	@mkdir -p $$(@D)
	$(FIT) local-exponent $(FIT_OPTS) $$<:/average/mean -o $$@
$$(THETA3_$(1)): $$(ENERGY3_$(1)) | $(FIT)
	@mkdir -p $$(@D)
	$(FIT) power-law $(FIT_OPTS) $$<:/average/mean --window $(THETA3_WIN_$(1)) -o $$@
$$(HAFF3_$(1)): $$(ENERGY3_$(1)) | $(FIT)
	@mkdir -p $$(@D)
	$(FIT) haff $(FIT_OPTS) $$<:/average/mean -o $$@
endef
$(foreach e,$(ES3),$(eval $(call SPHERES_ENSEMBLE,$(e))))

SPHERES_SIMS := $(foreach e,$(ES3),$(SIMS3_$(e)))

# The figure and its fits table (inputs per e, in the order of ES3).
FIG9_IN := $(foreach e,$(ES3),$(ENERGY3_$(e)) $(MASS3_$(e)) $(LARGEST3_$(e)) $(HAFF3_$(e)) $(THETA3_$(e)) \
             $(ZETA3_$(e)) $(ZETAL3_$(e)) $(LOCAL3_$(e)))
$(eval $(call STAMP_RULE,fig9,$(FIG9_IN)))
$(FIGURES)/fig9.png $(FIGURES)/fig9.svg $(FIGURES)/fig9.tsv $(FIGURES)/fig9.fits.tsv &: \
    $(FIG9_IN) $(FIGURES)/.fig9.inputs $(FIGSRC)/fig9.sh $(FIGSRC)/fig9.gp $(FIG_LIBS) | $(FIT)
	$(FIG_ENV) L3=$(L3) THETA_WINS="$(foreach e,$(ES3),$(call wtag,$(THETA3_WIN_$(e))))" \
	  ZETA_WINS="$(foreach e,$(ES3),$(call wtag,$(ZETA3_WIN_$(e))))" $(FIGSRC)/fig9.sh "$(ES3)" \
	  "$(foreach e,$(ES3),$(ENERGY3_$(e)))" "$(foreach e,$(ES3),$(MASS3_$(e)))" \
	  "$(foreach e,$(ES3),$(LARGEST3_$(e)))" "$(foreach e,$(ES3),$(HAFF3_$(e)))" \
	  "$(foreach e,$(ES3),$(THETA3_$(e)))" "$(foreach e,$(ES3),$(ZETA3_$(e)))" \
	  "$(foreach e,$(ES3),$(ZETAL3_$(e)))" "$(foreach e,$(ES3),$(LOCAL3_$(e)))"
.PHONY: fig9
fig9: $(FIGURES)/fig9.png $(FIGURES)/fig9.svg $(FIGURES)/fig9.tsv $(FIGURES)/fig9.fits.tsv
sims: $(SPHERES_SIMS)
