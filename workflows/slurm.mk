# Job arrays for a cluster's Slurm (issue #22, item 4): a target writes an sbatch script with
# one array task per independent unit of work (a validation case, a sweep's speed), each task
# a make of that unit's file target, so a task resubmitted after a failure or a time limit
# resumes where it stopped (run-rules.mk) and finished units are not redone. Included by
# validate.mk and sweep.mk, which call slurm_array.
#
#   SBATCH_FLAGS     extra "#SBATCH" options, e.g. "--partition=short --time=04:00:00"
#   SLURM_MAX_RUNNING  at most this many tasks at once (the array's %N)
#   SUBMIT=1         also submit: the array, then the collect job (afterany on the array)
#
# $(call slurm_array,SCRIPT,JOB_NAME,TARGETS,MAKEFILE,MAKE_VARIABLES,COLLECT_GOAL)
SBATCH_FLAGS ?=
SLURM_MAX_RUNNING ?=
SUBMIT ?=
SBATCH ?= sbatch

define slurm_array
	@mkdir -p $(dir $(1))logs
	@{ echo '#!/bin/bash'; \
	  echo '# Written by make $(2) (workflows/slurm.mk): one task per target below.'; \
	  echo '#SBATCH --job-name=$(2)'; \
	  echo '#SBATCH --array=0-$(words $(wordlist 2,$(words $(3)),$(3)))$(if $(SLURM_MAX_RUNNING),%$(SLURM_MAX_RUNNING))'; \
	  echo '#SBATCH --cpus-per-task=$(THREADS)'; \
	  echo '#SBATCH --output=$(dir $(1))logs/%x-%A_%a.log'; \
	  $(foreach f,$(SBATCH_FLAGS),echo '#SBATCH $(f)';) \
	  echo 'set -euo pipefail'; \
	  echo 'targets=($(3))'; \
	  echo 'target=$${targets[$$SLURM_ARRAY_TASK_ID]}'; \
	  echo 'echo "$(2): task $$SLURM_ARRAY_TASK_ID: $$target"'; \
	  echo 'exec make --no-print-directory -C $(ROOT)/workflows -f $(4) "$$target" $(5) THREADS=$${SLURM_CPUS_PER_TASK:-$(THREADS)}'; \
	} > $(1).tmp && chmod +x $(1).tmp && mv $(1).tmp $(1)
	@{ echo '#!/bin/bash'; \
	  echo '#SBATCH --job-name=$(2)-collect'; \
	  echo '#SBATCH --cpus-per-task=1'; \
	  echo '#SBATCH --output=$(dir $(1))logs/%x-%j.log'; \
	  $(foreach f,$(SBATCH_FLAGS),echo '#SBATCH $(f)';) \
	  echo 'exec make --no-print-directory -C $(ROOT)/workflows -f $(4) $(6) $(5)'; \
	} > $(1:.sbatch=-collect.sbatch).tmp && chmod +x $(1:.sbatch=-collect.sbatch).tmp && \
	  mv $(1:.sbatch=-collect.sbatch).tmp $(1:.sbatch=-collect.sbatch)
	@echo "$(2): $(words $(3)) tasks -> $(1) (collect: $(1:.sbatch=-collect.sbatch))"
	@if [ -n "$(SUBMIT)" ]; then \
	  id=$$($(SBATCH) --parsable $(1)); id=$${id%%;*}; \
	  cid=$$($(SBATCH) --parsable --dependency=afterany:$$id $(1:.sbatch=-collect.sbatch)); \
	  echo "$(2): submitted array $$id, collect job $${cid%%;*} after it"; \
	else echo "$(2): submit with SUBMIT=1, or: sbatch $(1), then make $(6) to collect"; fi
endef
