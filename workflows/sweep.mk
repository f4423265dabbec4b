# make sweep: the hydrocode's ballistic limit of one shield at several speeds (hvi-sweep,
# libcore/app/HviSweepTool.hpp). Per speed, the search starts at the ballistic limit
# equation's value and brackets the projectile diameter (PARAMETER=diameter) or the rear-wall
# thickness (PARAMETER=rear_wall) at which the simulated verdict flips, to TOLERANCE_MM; the
# runs of one speed follow each other, the speeds run side by side under make -j. Every point
# is a case directory (run-rules.mk), so a killed make resumes where it stopped, and the
# result is OUT/sweep.csv and OUT/sweep.svg (the limit, the equation's curve, the tests of the
# same shield).
#
#   make -C workflows sweep CASE=WPL-0341 PARAMETER=rear_wall SPEEDS="5.5 6.5 7.5" \
#        [RESOLUTION=0.08] [TOLERANCE_MM=0.25] [THREADS=1] [OUT=dir] [LAUNCH='srun -n1 -c8']
#   make -C workflows sweep PANEL=panel.json WRITER=foam2layers [CONSTRAINTS=c.json] ...
ROOT := $(abspath $(dir $(lastword $(MAKEFILE_LIST)))/..)
SWEEP_MK := $(abspath $(lastword $(MAKEFILE_LIST)))
BIN ?= $(ROOT)/build/tools
CASE ?=
PANEL ?=
WRITER ?=
CONSTRAINTS ?=
PARAMETER ?= diameter
SPEEDS ?= 5 6.5 8
TOLERANCE_MM ?= 0.1
RESOLUTION ?= 0.08
THREADS ?= 1
END_TIME_FLAG :=
MATERIALS ?=
MATERIALS_FLAG := $(if $(MATERIALS),--materials $(abspath $(MATERIALS)))
NAME := $(if $(CASE),$(CASE),$(basename $(notdir $(PANEL))))
OUT ?= out/sweep/$(NAME)-$(PARAMETER)-$(RESOLUTION)
override OUT := $(if $(filter /%,$(OUT)),$(OUT),$(ROOT)/$(OUT))

HVI_SWEEP := $(BIN)/hvi-sweep/hvi-sweep
SHIELD_FLAGS := $(if $(CASE),--case $(CASE),--panel $(abspath $(PANEL)) --writer $(WRITER) \
                  $(if $(CONSTRAINTS),--constraints $(abspath $(CONSTRAINTS))))
ifeq ($(strip $(CASE)$(PANEL)),)
$(error give the shield: CASE=<validation id> or PANEL=<scene writer input> WRITER=<writer>)
endif

.PHONY: sweep slurm-sweep
.DELETE_ON_ERROR:
# Keep each point's scene and run file (not .SECONDARY for everything: that would make the
# per-speed results intermediate, and a removed one would not be remade).
.PRECIOUS: $(OUT)/%/scene.json $(OUT)/%/run.h5

sweep: $(OUT)/sweep.csv

# Static pattern rules: the per-speed files are explicit targets, so a missing one is remade
# even when sweep.csv is newer than the others.
CRITICAL_FILES := $(foreach v,$(SPEEDS),$(OUT)/v$(v)/critical.json)
SPEC_FILES := $(foreach v,$(SPEEDS),$(OUT)/v$(v)/sweep.json)

$(OUT)/sweep.csv: $(CRITICAL_FILES)
	$(HVI_SWEEP) report --out-dir $(OUT) -o $@ --plot $(OUT)/sweep.svg
	@echo "sweep: $(words $(SPEEDS)) speeds -> $@, $(OUT)/sweep.svg"

$(SPEC_FILES): $(OUT)/v%/sweep.json:
	$(HVI_SWEEP) init $(SHIELD_FLAGS) --parameter $(PARAMETER) --speed-km-s $* \
	  --tolerance-mm $(TOLERANCE_MM) --out-dir $(OUT)/v$*

# One point at a time: hvi-sweep names the next one from the verdicts so far (and writes
# critical.json when the search stops), a sub-make runs it through run-rules.mk.
$(CRITICAL_FILES): $(OUT)/v%/critical.json: $(OUT)/v%/sweep.json
	@set -e; while p=$$($(HVI_SWEEP) next $(OUT)/v$*); [ -n "$$p" ]; do \
	  $(MAKE) --no-print-directory -f $(SWEEP_MK) $$p/verdict.json; \
	  echo "sweep: v$*: $$(basename $$p) $$(grep -m1 '"verdict"' $$p/verdict.json | tr -d ' ,')"; \
	done

# The speeds as a Slurm job array (slurm.mk): one task per speed runs its search, the collect
# job the CSV and plot.
slurm-sweep:
	$(call slurm_array,$(OUT)/slurm/sweep.sbatch,hvi-sweep,$(CRITICAL_FILES),sweep.mk,$(if \
	  $(CASE),CASE=$(CASE),PANEL=$(abspath $(PANEL)) WRITER=$(WRITER) $(if \
	  $(CONSTRAINTS),CONSTRAINTS=$(abspath $(CONSTRAINTS)))) PARAMETER=$(PARAMETER) \
	  SPEEDS="$(SPEEDS)" TOLERANCE_MM=$(TOLERANCE_MM) RESOLUTION=$(RESOLUTION) BIN=$(BIN) \
	  OUT=$(OUT) $(if $(MATERIALS),MATERIALS=$(abspath $(MATERIALS))),sweep)

include $(ROOT)/workflows/run-rules.mk
include $(ROOT)/workflows/slurm.mk
