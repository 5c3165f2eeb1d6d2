# effect-viscoelastic.mk -- viscoelastic particles: the cooling of a dilute gas whose restitution follows
# the dissipative Hertz law, against kinetic theory and the t^(-5/3) law (docs/PHYSICS.md "Viscoelastic
# particles"), included by pipelines/effects/effects.mk.
#
#   make -f Makefile.study effects
#
# One run of pipelines/scenes/effect-viscoelastic.ini (seconds); the figure
# $(FIGURES)/effect-viscoelastic.png (and .svg, .tsv: time T T_theory; .fits.tsv: the late exponents) by
# pipelines/figures/effect-viscoelastic.sh and .gp.

VISCO_SIM := $(SIMD)/effects/viscoelastic/run1.h5
VISCO_SRC := $(FIGSRC)/effect-viscoelastic.sh $(FIGSRC)/effect-viscoelastic.gp

$(VISCO_SIM): $(SCENES)/effect-viscoelastic.ini | $(SIM)
	@mkdir -p $(@D)
	$(LAUNCH) $(SIM_RESUME) $(SIM) --scene $< --quiet --checkpoint-every $(CHECKPOINT_EVERY) -o $@
$(FIGURES)/effect-viscoelastic.png $(FIGURES)/effect-viscoelastic.svg $(FIGURES)/effect-viscoelastic.tsv \
$(FIGURES)/effect-viscoelastic.fits.tsv &: $(VISCO_SIM) $(SCENES)/effect-viscoelastic.ini $(VISCO_SRC) $(FIG_LIBS) | $(FIT)
	@mkdir -p $(FIGURES)
	$(FIG_ENV) $(FIGSRC)/effect-viscoelastic.sh $(VISCO_SIM) $(SCENES)/effect-viscoelastic.ini

effects: $(FIGURES)/effect-viscoelastic.png
