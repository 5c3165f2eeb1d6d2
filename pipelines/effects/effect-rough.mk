# effect-rough.mk -- rough particles: the translational and rotational temperatures of a cooling gas of
# rough disks and their ratio against the homogeneous cooling state's (docs/PHYSICS.md "Rough
# particles"), included by pipelines/effects/effects.mk.
#
#   make -f Makefile.study effects
#
# One run of pipelines/scenes/effect-rough.ini (seconds); the figure $(FIGURES)/effect-rough.png (and
# .svg, .tsv: time T_tr T_rot T_rot/T_tr collisions per particle; .fits.tsv: the theory's steady ratio
# and the run's mean ratio) by pipelines/figures/effect-rough.sh and .gp.

ROUGH_SIM := $(SIMD)/effects/rough/run1.h5
ROUGH_SRC := $(FIGSRC)/effect-rough.sh $(FIGSRC)/effect-rough.gp

$(ROUGH_SIM): $(SCENES)/effect-rough.ini | $(SIM)
	@mkdir -p $(@D)
	$(LAUNCH) $(SIM_RESUME) $(SIM) --scene $< --seed 1 --quiet --checkpoint-every $(CHECKPOINT_EVERY) -o $@
$(FIGURES)/effect-rough.png $(FIGURES)/effect-rough.svg $(FIGURES)/effect-rough.tsv \
$(FIGURES)/effect-rough.fits.tsv &: $(ROUGH_SIM) $(SCENES)/effect-rough.ini $(ROUGH_SRC) $(FIG_LIBS) | $(FIT)
	@mkdir -p $(FIGURES)
	$(FIG_ENV) $(FIGSRC)/effect-rough.sh $(ROUGH_SIM) $(SCENES)/effect-rough.ini

effects: $(FIGURES)/effect-rough.png
