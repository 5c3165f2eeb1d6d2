# finite-size.mk -- the finite-size study of m(t) (Fig. 8), included by Makefile.study.
#
#   make -f Makefile.study finite-size [SCALE=large]      # simulations, per-run results, fig8
#   make -f Makefile.study fig8 SCALE=large FS_FROM_RESULTS=yes   # fig8 from the committed results only
#   make -f Makefile.study plan SCALE=large               # CPU hours and disk per cell
#
# The paper's question: is the late-time growth of the clusters, amplitude as well as exponent,
# independent of e? At one box size the answer is confounded with finite size, so every e is run at
# several box edges FS_LS, FS_NRUN runs each. The answer is read in the lengths l(t) and l_C(t), each up
# to its own onset of finite size, and in the mean mass m(t) only before the giant cluster forms (t_g,
# whose dependence on L says whether the giant is a box effect); docs/PHYSICS.md "Finite size" and
# "The answer in lengths". The per-scale settings (FS_LS, FS_NRUN, FS_TMAX_e) are in
# Makefile.study's scale block.
#
# Layout: a cell is (e, L, t_max). Its simulations are $(SIMD)/ens/e<e>-L<L>-t<t_max>/run<k>.h5, the
# same directories as the ensembles of Figs. 3-6, so a cell that equals the study's ensemble is not
# run twice. Each run's small result file, $(FS_RESULTS)/e<e>-L<L>-t<t_max>/run<k>.h5 (gg-cluster's
# m(t) and giant cluster, l(t), C(r, t) and l_C(t), the velocities, the run's E(t), its parameters,
# provenance and CPU seconds; pipelines/finite-size/collect.sh), is all fig8 reads. At SCALE=large the
# results live in the repository (results/finite-size/), so the figure and its rows of
# figures/summary.md can be rebuilt without the simulations; a result whose simulation is absent is
# taken as it is.

FS_DIR := pipelines/finite-size
# Where the per-run results go: committed at SCALE=large, with the runs otherwise; one folder per set of
# cluster options (CTAG), so a changed analysis option makes new results instead of reusing stale ones.
FS_RESULTS_ROOT ?= $(if $(filter large,$(SCALE)),results/finite-size,$(R)/finite-size)
FS_RESULTS := $(FS_RESULTS_ROOT)/$(CTAG)
# yes: fig8 from the result files present, no simulation started (the summary says what is missing).
FS_FROM_RESULTS ?= no
# Finite size sets in when m(t) of a box leaves that of the next larger box by more than FS_SIGMAS
# standard errors and by more than the fraction FS_MIN_DEV, at FS_CONSEC snapshots in a row, from
# t = FS_TFS_FROM on; fits end there (or at t_max).
FS_TFS_FROM ?= 10
FS_CONSEC ?= 3
FS_MIN_DEV ?= 0.05
# Start of the m(t) power-law window per e and of the amplitude window: the scale's ZETA_WIN_e and
# COLLAPSE_WIN starts unless set.
FS_ZETA_T1_0.5 ?= $(word 1,$(ZETA_WIN_0.5))
FS_ZETA_T1_0.7 ?= $(word 1,$(ZETA_WIN_0.7))
FS_ZETA_T1_0.9 ?= $(word 1,$(ZETA_WIN_0.9))
FS_AMP_T1 ?= $(word 1,$(COLLAPSE_WIN))
# Verdict on A(e)/A(0.5) = 1: 2-sigma intervals, "supported" only within +-FS_TOLERANCE (gg-fit extrapolate).
FS_SIGMAS ?= 2
FS_TOLERANCE ?= 0.1
# Width in decades of the late exponent's window (and of the one before it that says whether it has
# settled), and of the window of the ratio at equal times, both ending at the cell's last trusted time.
FS_LATE_DECADES ?= 0.5
# Cells that run past this time are searched for a step in the cluster count that their runs share
# (pipelines/figures/count-steps.sh), from this time on: the long runs' late regime.
FS_STEP_FROM ?= 1e4

# A cell's t_max and number of runs: the scale's per e, unless it sets FS_TMAX_<e>_L<L> or
# FS_NRUN_<e>_L<L> for that cell (a cell run longer keeps its first runs' trajectories: a run's
# data do not depend on its t_max).
fs_tmax = $(or $(FS_TMAX_$(1)_L$(2)),$(FS_TMAX_$(1)))
fs_nrun = $(or $(FS_NRUN_$(1)_L$(2)),$(FS_NRUN))
fs_runids = $(shell seq 1 $(call fs_nrun,$(1),$(2)))
# A cell's collapse cutoff (gg-sim --tc): none unless the scale sets FS_TC_<e>_L<L>. A cutoff makes
# another model (docs/PHYSICS.md "The answer without a common exponent"), so the cell's id says so.
fs_tc = $(FS_TC_$(1)_L$(2))
fs_id = e$(1)-L$(2)-t$(call fs_tmax,$(1),$(2))$(if $(call fs_tc,$(1),$(2)),-tc$(call fs_tc,$(1),$(2)))
# Every cell as e:L, and as e:L:t_max:runs:id for the figure and the plan.
FS_CELLS := $(foreach e,$(ES),$(foreach L,$(FS_LS),$(e):$(L)))
fs_e = $(word 1,$(subst :, ,$(1)))
fs_L = $(word 2,$(subst :, ,$(1)))
FS_PLAN := $(foreach c,$(FS_CELLS),$(c):$(call fs_tmax,$(call fs_e,$(c)),$(call fs_L,$(c))):$(call \
             fs_nrun,$(call fs_e,$(c)),$(call fs_L,$(c))):$(call fs_id,$(call fs_e,$(c)),$(call fs_L,$(c))))

# The definitions of a cluster the answer is checked with besides the paper's (CTAG): at box edge
# FS_DEF_L, every rho_c:w:connectivity of FS_DEFS (w: the coarse-graining half-width, gg-cluster
# --coarse), each in its own results folder beside the paper's. Empty: none.
FS_DEF_L ?=
FS_DEFS ?=
fs_def_tag = g$(GRID)w$(word 2,$(subst :, ,$(1)))rc$(word 1,$(subst :, ,$(1)))c$(word 3,$(subst :, ,$(1)))m$(MIN_SIZE)
fs_def_opts = --grid $(GRID) --coarse $(word 2,$(subst :, ,$(1))) --rho-c $(word 1,$(subst :, ,$(1))) \
              --connectivity $(word 3,$(subst :, ,$(1))) --min-size $(MIN_SIZE)
FS_DEF_TAGS := $(foreach d,$(FS_DEFS),$(call fs_def_tag,$(d)))

# Longer runs of a cell beside it, e:L:t_max:t_c:runs each (t_c "-" for none): used only for the late
# exponent past the cell's t_max and for the onset of finite size of the next smaller box beyond it
# (fig8.sh); the cell itself, with its own runs, keeps every other role. Empty: none.
FS_LONG ?=
fs_long_id = e$(word 1,$(1))-L$(word 2,$(1))-t$(word 3,$(1))$(if $(filter-out -,$(word 4,$(1))),-tc$(word 4,$(1)))

# One cell (1) e, (2) L, (3) t_max, (4) t_c (empty: none), (5) runs, (6) id: its simulations (one target
# per run, like the ensembles) and the per-run results. A result depends on its simulation unless the
# result exists and the simulation does not (committed results).
define FS_CELL
FS_SIMS_$(6) := $(foreach k,$(shell seq 1 $(5)),$(SIMD)/ens/$(6)/run$(k).h5)
FS_RES_$(6)  := $(foreach k,$(shell seq 1 $(5)),$(FS_RESULTS)/$(6)/run$(k).h5)
$(SIMD)/ens/$(6)/run%.h5: $(SCENES)/fig3-e$(1).ini | $(SIM)
	@mkdir -p $$(@D)
	$$(LAUNCH) $(SIM_RESUME) $(SIM) --scene $$< --L $(2) --t-max $(3) \
	  $(if $(4),--tc $(4)) --seed $$* --quiet --checkpoint-every $$(CHECKPOINT_EVERY) -o $$@
$(foreach k,$(shell seq 1 $(5)),$(eval $(call FS_RESULT,$(FS_RESULTS)/$(6)/run$(k).h5,$(SIMD)/ens/$(6)/run$(k).h5,$(GRID_OPTS) \
  --connectivity $(CONNECTIVITY) --min-size $(MIN_SIZE),$(FS_EVERY_ANALYSIS))))
endef
# What collect.sh needs to keep every analysis of a run besides its clusters (the paper's definition's
# results; the other definitions' keep their clusters only).
FS_EVERY_ANALYSIS := CORRELATE=$(CORRELATE) DOMAINS=$(DOMAINS) VELOCITY=$(VELOCITY) \
  CORRELATE_OPTS="$(GRID_OPTS) --a $(A)" DOMAINS_OPTS="$(GRID_OPTS) --phase $(PHASE)" \
  VELOCITY_OPTS="--grid $(GRID) --coarse $(COARSE) --a $(A)"
# A result (1) of simulation (2) with gg-cluster options (3) and, if (4) names them, every other analysis.
# A result that exists without its simulation (committed results) is taken as it is: no prerequisite,
# not even collect.sh, so that a newer collect.sh cannot start a collection that has nothing to read.
define FS_RESULT
$(1): $(if $(and $(wildcard $(1)),$(if $(wildcard $(2)),,absent)),,$(2) $(FS_DIR)/collect.sh) | $(CLUSTER) \
    $(if $(4),$(CORRELATE) $(DOMAINS) $(VELOCITY))
	@mkdir -p $$(@D)
	CLUSTER=$(CLUSTER) CLUSTER_OPTS="$(3)" $(4) $(FS_DIR)/collect.sh $(2) $$@
endef
$(foreach c,$(FS_CELLS),$(eval $(call FS_CELL,$(call fs_e,$(c)),$(call fs_L,$(c)),$(call fs_tmax,$(call fs_e,$(c)),$(call \
  fs_L,$(c))),$(call fs_tc,$(call fs_e,$(c)),$(call fs_L,$(c))),$(call fs_nrun,$(call fs_e,$(c)),$(call fs_L,$(c))),$(call \
  fs_id,$(call fs_e,$(c)),$(call fs_L,$(c))))))
fs_words = $(subst :, ,$(1))
$(foreach c,$(FS_LONG),$(eval $(call FS_CELL,$(word 1,$(call fs_words,$(c))),$(word 2,$(call fs_words,$(c))),$(word 3,$(call \
  fs_words,$(c))),$(filter-out -,$(word 4,$(call fs_words,$(c)))),$(word 5,$(call fs_words,$(c))),$(call fs_long_id,$(call \
  fs_words,$(c))))))
FS_LONG_IDS := $(foreach c,$(FS_LONG),$(call fs_long_id,$(call fs_words,$(c))))
# A longer cell as fig8.sh reads it: e:L:t_max:runs:id.
fs_long_plan = $(word 1,$(1)):$(word 2,$(1)):$(word 3,$(1)):$(word 5,$(1)):$(call fs_long_id,$(1))
# The other definitions' results of the cells at FS_DEF_L, from the same simulations.
FS_DEF_RES_ALL :=
$(foreach d,$(if $(FS_DEF_L),$(FS_DEFS)),$(foreach e,$(ES),$(foreach k,$(call fs_runids,$(e),$(FS_DEF_L)),$(eval \
  $(call FS_RESULT,$(FS_RESULTS_ROOT)/$(call fs_def_tag,$(d))/$(call fs_id,$(e),$(FS_DEF_L))/run$(k).h5,$(SIMD)/ens/$(call \
  fs_id,$(e),$(FS_DEF_L))/run$(k).h5,$(call fs_def_opts,$(d))))$(eval FS_DEF_RES_ALL += $(FS_RESULTS_ROOT)/$(call \
  fs_def_tag,$(d))/$(call fs_id,$(e),$(FS_DEF_L))/run$(k).h5))))

FS_IDS      := $(foreach c,$(FS_CELLS),$(call fs_id,$(call fs_e,$(c)),$(call fs_L,$(c)))) $(FS_LONG_IDS)
FS_SIMS_ALL := $(foreach i,$(FS_IDS),$(FS_SIMS_$(i)))
FS_RES_ALL  := $(foreach i,$(FS_IDS),$(FS_RES_$(i)))
FS_RES_IN   := $(if $(filter yes,$(FS_FROM_RESULTS)),$(wildcard $(FS_RES_ALL)),$(FS_RES_ALL))
FS_DEF_RES_IN := $(if $(filter yes,$(FS_FROM_RESULTS)),$(wildcard $(FS_DEF_RES_ALL)),$(FS_DEF_RES_ALL))
# The results of the simulations that have finished (no checkpoint beside them): what
# finite-size-collect makes while other runs of the study are still going.
fs_finished = $(and $(wildcard $(1)),$(if $(wildcard $(1).checkpoint.h5),,yes))
# The results (1) whose simulations have finished: a result's folder is its simulation's cell id.
fs_done = $(foreach r,$(1),$(if $(call fs_finished,$(SIMD)/ens/$(lastword $(subst /, ,$(dir $(r))))/$(notdir $(r))),$(r)))
FS_RES_DONE := $(call fs_done,$(FS_RES_ALL))
FS_DEF_RES_DONE := $(call fs_done,$(FS_DEF_RES_ALL))

.PHONY: finite-size finite-size-sims finite-size-results finite-size-collect finite-size-summary fig8
finite-size: fig8 finite-size-summary
finite-size-sims: $(FS_SIMS_ALL)
# Part of every study (fig8 is a figure of it): the Slurm path (submit.sh asks `make -n sims`) submits them.
sims: $(FS_SIMS_ALL)
finite-size-results: $(FS_RES_IN) $(FS_DEF_RES_IN)
finite-size-collect: $(FS_RES_DONE) $(FS_DEF_RES_DONE)

# Fig. 8 and its fits table from the per-run results; the plan (cells, runs, t_max) is passed along so
# the figure and the summary say which cells are complete and what is missing.
FIG8_IN := $(FS_RES_IN) $(FS_DEF_RES_IN) plan=$(subst $(space),_,$(FS_PLAN)) long=$(subst $(space),_,$(FS_LONG)) f=$(FS_TFS_FROM)_$(FS_CONSEC)_$(FS_MIN_DEV) \
           a=$(FS_AMP_T1) v=$(FS_SIGMAS)_$(FS_TOLERANCE) d=$(FS_DEF_L)_$(subst $(space),_,$(FS_DEFS)) l=$(FS_LATE_DECADES) s=$(FS_STEP_FROM)
$(eval $(call STAMP_RULE,fig8,$(FIG8_IN)))
$(FIGURES)/fig8.png $(FIGURES)/fig8.svg $(FIGURES)/fig8.tsv $(FIGURES)/fig8.fits.tsv &: \
    $(FS_RES_IN) $(FS_DEF_RES_IN) $(FIGURES)/.fig8.inputs $(FIGSRC)/fig8.sh $(FIGSRC)/fig8.gp $(FIGSRC)/answer.sh $(FIGSRC)/late-row.sh \
    $(FIGSRC)/giant.sh $(FIGSRC)/count-steps.sh $(FIGSRC)/fs-headline.awk \
    $(FIG_LIBS) | $(FIT)
	$(FIG_ENV) FS_RESULTS=$(FS_RESULTS) FS_TFS_FROM=$(FS_TFS_FROM) FS_CONSEC=$(FS_CONSEC) FS_MIN_DEV=$(FS_MIN_DEV) FS_AMP_T1=$(FS_AMP_T1) \
	  FS_ZETA_T1="$(foreach e,$(ES),$(FS_ZETA_T1_$(e)))" FS_SIGMAS=$(FS_SIGMAS) FS_TOLERANCE=$(FS_TOLERANCE) \
	  FS_WORK=$(ANAD)/finite-size FS_DIR=$(FS_DIR) FS_LATE_DECADES=$(FS_LATE_DECADES) FS_STEP_FROM=$(FS_STEP_FROM) \
	  FS_DEF_L=$(FS_DEF_L) FS_DEF_DIRS="$(foreach t,$(FS_DEF_TAGS),$(FS_RESULTS_ROOT)/$(t))" \
	  FS_LONG="$(foreach c,$(FS_LONG),$(call fs_long_plan,$(call fs_words,$(c))))" \
	  $(FIGSRC)/fig8.sh "$(ES)" "$(FS_LS)" "$(FS_PLAN)"
fig8: $(FIGURES)/fig8.png $(FIGURES)/fig8.svg $(FIGURES)/fig8.tsv $(FIGURES)/fig8.fits.tsv

# The finite-size section of the summary and the figure, kept beside the results they come from (at
# SCALE=large in the repository: results/finite-size/summary.md and fig8.png).
finite-size-summary: $(FS_RESULTS)/summary.md
$(FS_RESULTS)/summary.md: $(FIGURES)/fig8.fits.tsv $(FIGURES)/fig8.png $(FIGSRC)/summary-finite-size.awk
	@mkdir -p $(@D)
	awk -f $(FIGSRC)/summary-finite-size.awk $< > $@.tmp && mv $@.tmp $@
	cp $(FIGURES)/fig8.png $(@D)/fig8.png.tmp && mv $(@D)/fig8.png.tmp $(@D)/fig8.png
	@cat $@
