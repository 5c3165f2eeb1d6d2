# effect-mixture.mk -- the mixture effect (included by pipelines/effects/effects.mk): one run of the
# binary mixture of pipelines/scenes/effect-mixture.ini, and its figure: the temperatures of the two
# species T_1(t), T_2(t) and their ratio against Garzo & Dufty's (docs/PHYSICS.md "Mixtures";
# pipelines/figures/effect-mixture.sh).

MIXTURE_RUN := $(SIMD)/effects/mixture/run1.h5

$(MIXTURE_RUN): $(SCENES)/effect-mixture.ini | $(SIM)
	@mkdir -p $(@D)
	$(LAUNCH) $(SIM_RESUME) $(SIM) --scene $< --seed 1 --quiet --checkpoint-every $(CHECKPOINT_EVERY) -o $@

$(FIGURES)/effect-mixture.png $(FIGURES)/effect-mixture.svg $(FIGURES)/effect-mixture.tsv &: \
    $(MIXTURE_RUN) $(FIGSRC)/effect-mixture.sh $(FIGSRC)/effect-mixture.gp $(FIG_LIBS) | $(FIT)
	@mkdir -p $(FIGURES)
	$(FIG_ENV) $(FIGSRC)/effect-mixture.sh $(MIXTURE_RUN)

effects: $(FIGURES)/effect-mixture.png
