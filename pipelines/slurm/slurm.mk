# slurm.mk -- Slurm targets of the study, included by Makefile.study:
#   -include pipelines/slurm/slurm.mk
# Uses Makefile.study's SELF, SCALE, BUILD, RUNS, FIGURES and TOOLS. Before it is included, the same
# targets work with  make -f Makefile.study -f pipelines/slurm/slurm.mk <target>.
#
#   make -f Makefile.study slurm-submit SCALE=paper [SLURM_SUBMIT_OPTS='--sbatch "--account=x" --wait']
#       job arrays (one per ensemble, array index = seed) + a dependent analysis job (pipelines/slurm/submit.sh)
#   make -f Makefile.study test-slurm
#       test (CI runs it after `make test`): installs slurm-wlm if missing, starts a private single-node Slurm (slurmctld + slurmd,
#       state under a temporary directory), runs SCALE=quick locally, through srun (LAUNCH) and through
#       the job arrays, compares the results, stops the daemons it started (by PID)
#   make -f Makefile.study slurm-scaling   measure SCALE=quick simulations on 1 and 2 CPUs through srun
#
# Inside an allocation, the simulations of any target run as job steps with
#   make -f Makefile.study -j64 LAUNCH='srun -n1 -c1 --exact' SCALE=paper
# (complete batch script: pipelines/slurm/study.sbatch).

SLURM_DIR ?= pipelines/slurm
# test-slurm: TEST_SLURM_OPTS=--munge authenticates with munge (a private munged) instead of auth/none;
# --keep keeps the temporary directory (runs, logs, slurm.conf) even when the test passes.
TEST_SLURM_OPTS ?=
SLURM_SUBMIT_OPTS ?=
SLURM_SCALING_OPTS ?=

.PHONY: test-slurm slurm-submit slurm-tools slurm-scaling

# submit.sh gets the variables as arguments (it drops MAKEFLAGS: the jobs cannot use this make's
# jobserver): the four layout variables, then every variable of this make's command line but ours.
SLURM_MAKEVARS = 'SCALE=$(SCALE)' 'BUILD=$(BUILD)' 'RUNS=$(RUNS)' 'FIGURES=$(FIGURES)' \
  $(foreach v,$(sort $(.VARIABLES)),$(if $(filter command line,$(origin $(v))),$(if \
    $(filter SLURM_% TEST_SLURM_%,$(v)),,'$(v)=$($(v))')))

test-slurm: | $(TOOLS)
	SELF='$(SELF)' BUILD='$(BUILD)' $(SLURM_DIR)/test-slurm.sh $(TEST_SLURM_OPTS)

slurm-scaling: | $(TOOLS)
	SELF='$(SELF)' BUILD='$(BUILD)' $(SLURM_DIR)/scaling.sh $(SLURM_SCALING_OPTS)

slurm-submit:
	$(SLURM_DIR)/submit.sh -f $(SELF) $(SLURM_SUBMIT_OPTS) $(SLURM_MAKEVARS)

# Helpers for submit.sh: build the tools if missing; print a variable as make sees it.
slurm-tools: | $(TOOLS)
slurm-print-%:
	@echo 'SLURM-VAR=$($*)'
