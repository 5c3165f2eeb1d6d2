# effects.mk -- one short figure per physical effect a scene may add to the cooling gas (rough
# particles, a driven gas, a mixture), included by Makefile.study.
#
#   make -f Makefile.study effects
#
# Each effect has a file of its own here, effect-<name>.mk, with its scene (pipelines/scenes/
# effect-<name>.ini), its runs under $(SIMD)/effects/<name>/ and its figure $(FIGURES)/effect-<name>.png;
# each adds its figure to `effects`. The physics each figure is checked against: docs/PHYSICS.md.

.PHONY: effects
effects:
include $(sort $(wildcard pipelines/effects/effect-*.mk))
