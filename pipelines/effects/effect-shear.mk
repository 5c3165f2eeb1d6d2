# effect-shear.mk -- uniform shear flow: a dilute granular gas sheared with Lees-Edwards images settles
# into the steady state of kinetic theory, its flow linear across the box (docs/PHYSICS.md "Uniform
# shear flow"), included by pipelines/effects/effects.mk.
#
#   make -f Makefile.study effects
#
# One run of pipelines/scenes/effect-shear.ini (seconds), its profiles along y averaged over the
# snapshots (gg-velocity --profile y), and the figure $(FIGURES)/effect-shear.png (and .svg, .tsv: time
# a* P*_xx P*_yy P*_zz P*_xy; .profile.tsv: height n u_x u_x_err T; .fits.tsv: the steady values and
# Grad's) by pipelines/figures/effect-shear.sh and .gp.

SHEAR_SIM     := $(SIMD)/effects/shear/run1.h5
SHEAR_PROFILE := $(ANAD)/effects/shear/run1.profile.h5
SHEAR_SRC     := $(FIGSRC)/effect-shear.sh $(FIGSRC)/effect-shear.gp

$(SHEAR_SIM): $(SCENES)/effect-shear.ini | $(SIM)
	@mkdir -p $(@D)
	$(LAUNCH) $(SIM_RESUME) $(SIM) --scene $< --quiet --checkpoint-every $(CHECKPOINT_EVERY) -o $@
$(SHEAR_PROFILE): $(SHEAR_SIM) | $(VELOCITY)
	@mkdir -p $(@D)
	$(VELOCITY) --quiet $< --profile y -o $@
$(FIGURES)/effect-shear.png $(FIGURES)/effect-shear.svg $(FIGURES)/effect-shear.tsv $(FIGURES)/effect-shear.profile.tsv \
$(FIGURES)/effect-shear.fits.tsv &: $(SHEAR_SIM) $(SHEAR_PROFILE) $(SCENES)/effect-shear.ini $(SHEAR_SRC) $(FIG_LIBS) | $(FIT)
	@mkdir -p $(FIGURES)
	$(FIG_ENV) $(FIGSRC)/effect-shear.sh $(SHEAR_SIM) $(SHEAR_PROFILE) $(SCENES)/effect-shear.ini

effects: $(FIGURES)/effect-shear.png
