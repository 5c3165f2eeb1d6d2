# accuracy.mk -- "what accuracy costs in time", included by Makefile.study:
#
#   make -f Makefile.study accuracy [ACC_L=128 ACC_LREF=512 ...]
#
# writes $(FIGURES)/accuracy.png, .svg (gnuplot), .tsv (one row per knob value and quantity) and .md (the same
# as markdown tables, with the reference and its cost). For each knob: the CPU seconds of the simulations and
# analyses behind a number, against that number (zeta, theta, the amplitude ratio, l(t_max), E(t), m(t)) and
# its deviation from a high-accuracy reference. Knobs (each varied alone from the base point):
#   ensemble size      runs 1..R of ACC_RUNS at L = ACC_L                       vs the reference (L = ACC_LREF)
#   box size L         ACC_LS (+ ACC_L), ACC_RUNS_L runs each                   vs the reference
#   run length t_max   ACC_TMAXS (+ ACC_TMAX) at L = ACC_L, fit windows [t1, t_max]   vs the reference
#   collapse cutoff    ACC_CUTS (+ ACC_CUT) at L = ACC_CUT_L, same seeds        vs ACC_CUT_REF (smallest t_c);
#                      the cheapest that passes is named (cutoff-choice.awk)
#   snapshots          ACC_SNAPS (+ ACC_SNAP): per decade, float/double, same runs    vs ACC_SNAP_REF
#   coarse-graining    ACC_CGS on the reference runs                            vs the default (grid 1, w 1, rho_c 0.5)
#   fit windows        ACC_ZWINS / ACC_CWINS on the reference runs              vs the base windows
# Simulations (each run its own cached target, prefixed by $(LAUNCH)) and per-run analyses (gg-cluster,
# gg-domains) are separate targets from the cheap table step (averages, fits, table, figure:
# pipelines/accuracy/table.sh). Each of them records its CPU seconds in TARGET.cpu (pipelines/accuracy/timed.sh).
# Layout: $(RUNS)/accuracy/sim/e<e>-L<L>-t<t_max>-<cutoff>-<snapshots>/run<seed>.h5 (+ .cpu),
#         $(RUNS)/accuracy/ana/<same>/run<seed>.{cluster,domains}-g<grid>w<coarse>rc<rho_c>.h5 (+ .cpu),
#         $(RUNS)/accuracy/fits/ (averages and fits, remade by every table step).
# Tags: cutoff tc<t_c> | d<delta> | none; snapshots s<per decade>f (float) | s<per decade>d (double).
# Cost of the defaults: pipelines/accuracy/README.md;
# `accuracy` runs ACC_JOBS (default: all cores) jobs at once unless make was given -j. README: pipelines/accuracy/README.md.

ACC_DIR  := pipelines/accuracy
ACCR     := $(RUNS)/accuracy

ACC_E        ?= 0.5
ACC_E2       ?= 0.7
ACC_TMAX     ?= 1000
ACC_CUT      ?= tc1e-4
ACC_SNAP     ?= s8f
ACC_L        ?= 128
ACC_RUNS     ?= 10
ACC_RS       ?= 3 5 10
ACC_LS       ?= 64 256
ACC_RUNS_L   ?= 5
ACC_LREF     ?= 512
ACC_RUNS_REF ?= 3
# The cutoff is tested in the study's own box (L = 256): at L = 128 three runs resolve only ~40% in m(t)
# after t = 100. The reference t_c = 1e-5 is ten times below the study's t_c = 1e-4 (t_c = 1e-6 costs a
# heavy-tailed 3x more and moved nothing at L = 128).
ACC_CUTS     ?= tc1e-3 d1e-2 d1e-3 d1e-4 none
ACC_CUT_REF  ?= tc1e-5
ACC_CUT_RUNS ?= 3
ACC_CUT_L    ?= 256
# E(t), m(t) of the cutoff rows: largest deviation over 1 <= t <= ACC_TSPLIT and over ACC_TSPLIT < t <= t_max
ACC_TSPLIT   ?= 100
ACC_SNAPS    ?= s4f s16f s32f s8d
ACC_SNAP_REF ?= s32d
ACC_SNAP_RUNS ?= 3
ACC_TMAXS    ?= 300 3000
ACC_TMAX_RUNS ?= 5
# Fit windows: zeta (m of e = ACC_E), theta (E of ACC_E), amplitude ratio A(ACC_E2)/A(ACC_E) (gg-fit collapse);
# t_max rows fit over [first number, t_max]. Variants on the reference runs: FIRST_LAST pairs.
ACC_ZWIN     ?= 100 1000
ACC_TWIN     ?= 100 1000
ACC_CWIN     ?= 300 1000
ACC_ZWINS    ?= 30_1000 300_1000 100_500
ACC_CWINS    ?= 100_1000 500_1000
# Coarse-graining variants grid:coarse:rho_c (the base is 1:1:0.5, the study's default).
ACC_CGS      ?= 0.5:1:0.5 2:1:0.5 1:0:0.5 1:2:0.5 1:1:0.4 1:1:0.6
ACC_CG0      := 1:1:0.5

# ------------------------------------------------------------------------------------------------ names
acc_id  = e$(1)-L$(2)-t$(3)-$(4)-$(5)
acc_cg  = g$(word 1,$(subst :, ,$(1)))w$(word 2,$(subst :, ,$(1)))rc$(word 3,$(subst :, ,$(1)))
acc_cutflags = $(if $(filter none,$(1)),--tc 0 --delta 0,$(if $(filter tc%,$(1)),--tc $(patsubst tc%,%,$(1)) --delta 0,--tc 0 --delta $(patsubst d%,%,$(1))))
acc_snapflags = --snapshots-per-decade $(patsubst s%d,%,$(patsubst s%f,%,$(1))) --float-snapshots=$(if $(filter %f,$(1)),true,false)
# acc_runs(id, n): run files 1..n of a simulation directory
acc_runs = $(foreach k,$(shell seq 1 $(2)),$(ACCR)/sim/$(1)/run$(k).h5)

ACC_LS_X    := $(filter-out $(ACC_L) $(ACC_LREF),$(ACC_LS))
ACC_CUTS_X  := $(filter-out $(ACC_CUT) $(ACC_CUT_REF),$(ACC_CUTS))
ACC_SNAPS_X := $(filter-out $(ACC_SNAP) $(ACC_SNAP_REF),$(ACC_SNAPS))
ACC_TMAXS_X := $(filter-out $(ACC_TMAX),$(ACC_TMAXS))
# numeric max and sort of a list of numbers
acc_max   = $(lastword $(shell printf '%s\n' $(1) | sort -g))
acc_nsort = $(shell printf '%s\n' $(1) | sort -gu)

# Every simulation directory as e:L:t:cut:snap:runs (runs = how many seeds it needs).
ACC_CFGS := $(ACC_E):$(ACC_L):$(ACC_TMAX):$(ACC_CUT):$(ACC_SNAP):$(call acc_max,$(ACC_RUNS) $(ACC_CUT_RUNS) $(ACC_SNAP_RUNS) $(ACC_TMAX_RUNS)) \
            $(ACC_E2):$(ACC_L):$(ACC_TMAX):$(ACC_CUT):$(ACC_SNAP):$(ACC_RUNS) \
            $(foreach L,$(ACC_LS_X),$(ACC_E):$(L):$(ACC_TMAX):$(ACC_CUT):$(ACC_SNAP):$(ACC_RUNS_L) \
                                    $(ACC_E2):$(L):$(ACC_TMAX):$(ACC_CUT):$(ACC_SNAP):$(ACC_RUNS_L)) \
            $(ACC_E):$(ACC_LREF):$(ACC_TMAX):$(ACC_CUT):$(ACC_SNAP):$(ACC_RUNS_REF) \
            $(ACC_E2):$(ACC_LREF):$(ACC_TMAX):$(ACC_CUT):$(ACC_SNAP):$(ACC_RUNS_REF) \
            $(foreach c,$(ACC_CUT) $(ACC_CUTS_X) $(ACC_CUT_REF),$(ACC_E):$(ACC_CUT_L):$(ACC_TMAX):$(c):$(ACC_SNAP):$(ACC_CUT_RUNS)) \
            $(foreach s,$(ACC_SNAPS_X) $(ACC_SNAP_REF),$(ACC_E):$(ACC_L):$(ACC_TMAX):$(ACC_CUT):$(s):$(ACC_SNAP_RUNS)) \
            $(foreach t,$(ACC_TMAXS_X),$(ACC_E):$(ACC_L):$(t):$(ACC_CUT):$(ACC_SNAP):$(ACC_TMAX_RUNS))
acc_f = $(word $(2),$(subst :, ,$(1)))
acc_cfg_id = $(call acc_id,$(call acc_f,$(1),1),$(call acc_f,$(1),2),$(call acc_f,$(1),3),$(call acc_f,$(1),4),$(call acc_f,$(1),5))

# ---------------------------------------------------------------------------------------- simulations
# One pattern rule per simulation directory; seed = run number. Runs with a cutoff other than the base one
# may collapse (no cutoff always does at e = 0.5): that is recorded as a result (timed.sh --allow-collapse).
define ACC_SIM_RULE
$(ACCR)/sim/$(call acc_id,$(1),$(2),$(3),$(4),$(5))/run%.h5: $(SCENES)/fig3-e$(1).ini | $(SIM)
	@mkdir -p $$(@D)
	$$(LAUNCH) $(ACC_DIR)/timed.sh $(if $(filter $(ACC_CUT),$(4)),,--allow-collapse) $$@ $(SIM) --scene $$< \
	  --L $(2) --t-max $(3) $(call acc_cutflags,$(4)) $(call acc_snapflags,$(5)) --seed $$* --quiet -o $$@.part.h5
endef
# unique directories (e:L:t:cut:snap), one rule each
ACC_DIRCFGS := $(sort $(foreach c,$(ACC_CFGS),$(subst $(space),:,$(wordlist 1,5,$(subst :, ,$(c))))))
$(foreach c,$(ACC_DIRCFGS),$(eval $(call ACC_SIM_RULE,$(call acc_f,$(c),1),$(call acc_f,$(c),2),$(call acc_f,$(c),3),$(call acc_f,$(c),4),$(call acc_f,$(c),5))))

ACC_SIMS := $(sort $(foreach c,$(ACC_CFGS),$(call acc_runs,$(call acc_cfg_id,$(c)),$(call acc_f,$(c),6))))

# ------------------------------------------------------------------------------------------ analyses
# Per run, per coarse-graining: gg-cluster (m(t)) and gg-domains (l(t)), with their CPU seconds.
define ACC_ANA_RULE
$(ACCR)/ana/%.cluster-$(call acc_cg,$(1)).h5: $(ACCR)/sim/%.h5 | $(CLUSTER)
	@mkdir -p $$(@D)
	$(ACC_DIR)/timed.sh $$@ $(CLUSTER) --quiet $$< -o $$@.part.h5 --grid $(word 1,$(subst :, ,$(1))) \
	  --coarse $(word 2,$(subst :, ,$(1))) --rho-c $(word 3,$(subst :, ,$(1)))
$(ACCR)/ana/%.domains-$(call acc_cg,$(1)).h5: $(ACCR)/sim/%.h5 | $(DOMAINS)
	@mkdir -p $$(@D)
	$(ACC_DIR)/timed.sh $$@ $(DOMAINS) --quiet $$< -o $$@.part.h5 --grid $(word 1,$(subst :, ,$(1))) \
	  --coarse $(word 2,$(subst :, ,$(1))) --rho-c $(word 3,$(subst :, ,$(1)))
endef
$(foreach g,$(sort $(ACC_CG0) $(ACC_CGS)),$(eval $(call ACC_ANA_RULE,$(g))))

# Default coarse-graining for every run (a collapsed run is analysed up to its collapse); every
# coarse-graining for the reference runs.
ACC_REF_SIMS := $(call acc_runs,$(call acc_id,$(ACC_E),$(ACC_LREF),$(ACC_TMAX),$(ACC_CUT),$(ACC_SNAP)),$(ACC_RUNS_REF)) \
                $(call acc_runs,$(call acc_id,$(ACC_E2),$(ACC_LREF),$(ACC_TMAX),$(ACC_CUT),$(ACC_SNAP)),$(ACC_RUNS_REF))
acc_ana = $(patsubst $(ACCR)/sim/%.h5,$(ACCR)/ana/%.$(2)-$(call acc_cg,$(3)).h5,$(1))
ACC_ANAS := $(foreach t,cluster domains,$(call acc_ana,$(ACC_SIMS),$(t),$(ACC_CG0)) \
              $(foreach g,$(ACC_CGS),$(call acc_ana,$(ACC_REF_SIMS),$(t),$(g))))

# ---------------------------------------------------------------------------------------- table, figure
ACC_ENV := FIT=$(FIT) GNUPLOT=$(GNUPLOT) ACC_DIR=$(ACC_DIR) ACCR=$(ACCR) OUT=$(FIGURES) \
  ACC_E='$(ACC_E)' ACC_E2='$(ACC_E2)' ACC_TMAX='$(ACC_TMAX)' ACC_CUT='$(ACC_CUT)' ACC_SNAP='$(ACC_SNAP)' \
  ACC_L='$(ACC_L)' ACC_RUNS='$(ACC_RUNS)' ACC_RS='$(ACC_RS)' ACC_LS='$(call acc_nsort,$(ACC_LS_X) $(ACC_L))' \
  ACC_RUNS_L='$(ACC_RUNS_L)' ACC_LREF='$(ACC_LREF)' ACC_RUNS_REF='$(ACC_RUNS_REF)' \
  ACC_CUTS='$(ACC_CUT) $(ACC_CUTS_X)' ACC_CUT_REF='$(ACC_CUT_REF)' ACC_CUT_RUNS='$(ACC_CUT_RUNS)' ACC_CUT_L='$(ACC_CUT_L)' ACC_TSPLIT='$(ACC_TSPLIT)' \
  ACC_SNAPS='$(ACC_SNAP) $(ACC_SNAPS_X)' ACC_SNAP_REF='$(ACC_SNAP_REF)' ACC_SNAP_RUNS='$(ACC_SNAP_RUNS)' \
  ACC_TMAXS='$(call acc_nsort,$(ACC_TMAXS_X) $(ACC_TMAX))' ACC_TMAX_RUNS='$(ACC_TMAX_RUNS)' \
  ACC_ZWIN='$(ACC_ZWIN)' ACC_TWIN='$(ACC_TWIN)' ACC_CWIN='$(ACC_CWIN)' ACC_ZWINS='$(ACC_ZWINS)' \
  ACC_CWINS='$(ACC_CWINS)' ACC_CGS='$(ACC_CGS)' ACC_CG0='$(ACC_CG0)'
ACC_OUTS := $(FIGURES)/accuracy.png $(FIGURES)/accuracy.svg $(FIGURES)/accuracy.tsv $(FIGURES)/accuracy.md

# The stamp holds the configuration: changing an analysis-only setting (a window) redoes the table.
$(eval $(call STAMP_RULE,accuracy,$(subst $(space),_,$(ACC_ENV))))
$(ACC_OUTS) &: $(ACC_REF_SIMS) $(ACC_SIMS) $(ACC_ANAS) $(FIGURES)/.accuracy.inputs $(ACC_DIR)/table.sh $(ACC_DIR)/accuracy.gp \
    $(ACC_DIR)/cutoff-choice.awk \
    | $(FIT)
	$(ACC_ENV) $(ACC_DIR)/table.sh

# `accuracy` runs its simulations ACC_JOBS at a time (default: one per core) unless make was given -j.
ACC_JOBS ?= $(NPROC)
.PHONY: accuracy-outputs accuracy-sims accuracy-analyses accuracy-clean
accuracy:
	+$(MAKE) -f $(SELF) $(if $(filter -j%,$(MAKEFLAGS)),,-j$(ACC_JOBS)) accuracy-outputs
accuracy-outputs: $(ACC_OUTS)
accuracy-sims: $(ACC_SIMS)
accuracy-analyses: $(ACC_ANAS)
# Removes the analyses, fits and outputs; keeps the simulations (rm -rf $(ACCR) removes those too).
accuracy-clean:
	rm -rf $(ACCR)/ana $(ACCR)/fits $(ACC_OUTS) $(FIGURES)/.accuracy.inputs
