# effect-walls.mk -- walls and gravity: the density and temperature profiles of an elastic gas over a
# thermal wall against hydrostatics (docs/PHYSICS.md "Walls and gravity"), included by
# pipelines/effects/effects.mk.
#
#   make -f Makefile.study effects
#
# One run of pipelines/scenes/effect-walls.ini (seconds), its profiles along the walls' axis averaged
# over the snapshots (gg-velocity --profile y), and the figure $(FIGURES)/effect-walls.png (and .svg,
# .tsv: height n n_err T T_err n_Henderson n_barometric; .fits.tsv: the profile's deviations) by
# pipelines/figures/effect-walls.sh and .gp.

WALLS_SIM     := $(SIMD)/effects/walls/run1.h5
WALLS_PROFILE := $(ANAD)/effects/walls/run1.profile.h5
WALLS_SRC     := $(FIGSRC)/effect-walls.sh $(FIGSRC)/effect-walls.gp

$(WALLS_SIM): $(SCENES)/effect-walls.ini | $(SIM)
	@mkdir -p $(@D)
	$(LAUNCH) $(SIM_RESUME) $(SIM) --scene $< --quiet --checkpoint-every $(CHECKPOINT_EVERY) -o $@
$(WALLS_PROFILE): $(WALLS_SIM) | $(VELOCITY)
	@mkdir -p $(@D)
	$(VELOCITY) --quiet $< --profile y -o $@
$(FIGURES)/effect-walls.png $(FIGURES)/effect-walls.svg $(FIGURES)/effect-walls.tsv \
$(FIGURES)/effect-walls.fits.tsv &: $(WALLS_PROFILE) $(SCENES)/effect-walls.ini $(WALLS_SRC) $(FIG_LIBS)
	@mkdir -p $(FIGURES)
	$(FIG_ENV) $(FIGSRC)/effect-walls.sh $(WALLS_PROFILE) $(SCENES)/effect-walls.ini

effects: $(FIGURES)/effect-walls.png
