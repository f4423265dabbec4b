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
#   make -C workflows -f sweep.mk sweep-keep CASE=... (the same settings): keep the results
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

# Kept results (as validate.mk's kept verdicts): `make sweep-keep` copies each finished speed's
# sweep.json and critical.json into KEPT (committed to the repository); a speed kept there is
# taken instead of its search, so a sweep spans sessions and its picture regenerates without
# the runs. Kept results hold for the solver and settings that made them: after a change to
# the physics or to TOLERANCE_MM, remove KEPT's speeds and run again.
KEPT ?= $(ROOT)/data/validation/sweeps/$(notdir $(OUT))

.PHONY: sweep slurm-sweep sweep-keep
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

sweep-keep:
	@n=0; for v in $(SPEEDS); do if [ -f $(OUT)/v$$v/critical.json ]; then \
	  mkdir -p $(KEPT)/v$$v; for f in sweep.json critical.json; do \
	    sed 's|$(ROOT)/||g' $(OUT)/v$$v/$$f > $(KEPT)/v$$v/$$f; done; \
	  n=$$((n+1)); fi; done; echo "sweep-keep: $$n speeds -> $(KEPT)"

$(SPEC_FILES): $(OUT)/v%/sweep.json:
	@if [ -f $(KEPT)/v$*/sweep.json ]; then mkdir -p $(@D); cp -p $(KEPT)/v$*/sweep.json $@; \
	  else $(HVI_SWEEP) init $(SHIELD_FLAGS) --parameter $(PARAMETER) --speed-km-s $* \
	  --tolerance-mm $(TOLERANCE_MM) --out-dir $(OUT)/v$*; fi

# One point at a time: hvi-sweep names the next one from the verdicts so far (and writes
# critical.json when the search stops), a sub-make runs it through run-rules.mk.
$(CRITICAL_FILES): $(OUT)/v%/critical.json: $(OUT)/v%/sweep.json
	@set -e; if [ -f $(KEPT)/v$*/critical.json ]; then cp -p $(KEPT)/v$*/critical.json $@; \
	  echo "sweep: v$*: kept in $(KEPT)"; exit 0; fi; \
	while p=$$($(HVI_SWEEP) next $(OUT)/v$*); [ -n "$$p" ]; do \
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
