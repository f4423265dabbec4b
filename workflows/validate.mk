# make validate: the verdicts of the validation cases against the tests (docs/validation.md).
ROOT := $(abspath $(dir $(lastword $(MAKEFILE_LIST)))/..)
VALIDATE_MK := $(abspath $(lastword $(MAKEFILE_LIST)))
BIN ?= $(ROOT)/build/tools
SET ?= quick
RESOLUTION ?= 0.04
THREADS ?= 1
END_TIME_US ?=
# VARIANT=NAME: a sensitivity study, the cases run with the material library
# workflows/materials/NAME.json laid over the built-in one (e.g. spall-0.8: every aluminium
# with a spall strength of 0.8 GPa), in their own OUT, kept apart (ARCHIVE below); the
# report of the default library shows their verdicts beside its own.
VARIANT ?=
# One directory per spacing, shared by the sets: a case run for one set counts for all.
# Relative OUT and REPORT are taken from the repository root (make -C changes directory).
OUT ?= out/validate$(if $(VARIANT),-$(VARIANT))/$(RESOLUTION)
REPORT ?= $(OUT)/validation.md
override OUT := $(if $(filter /%,$(OUT)),$(OUT),$(ROOT)/$(OUT))
override REPORT := $(if $(filter /%,$(REPORT)),$(REPORT),$(ROOT)/$(REPORT))

HVI_VALIDATE := $(BIN)/hvi-validate/hvi-validate
# Interleaved: the shield types in turn, so a validation stopped part-way has measured each.
CASES := $(shell $(HVI_VALIDATE) list --set $(SET) --interleave)
ifeq ($(strip $(CASES)),)
$(error hvi-validate listed no case for SET=$(SET): build the toolkit first (scripts/build.sh))
endif
# ONLY_CASES="ID ...": the cases of the set among these ids (a sensitivity study on quick
# ones; not ONLY, which the extreme suite uses).
ONLY_CASES ?=
ifneq ($(strip $(ONLY_CASES)),)
CASES := $(filter $(ONLY_CASES),$(CASES))
ifeq ($(strip $(CASES)),)
$(error none of ONLY_CASES="$(ONLY_CASES)" is a case of SET=$(SET) (hvi-validate list --set $(SET)))
endif
endif
END_TIME_FLAG := $(if $(END_TIME_US),--end-time-us $(END_TIME_US))
# MATERIALS=FILE: a material library laid over the built-in one (hvi-run --materials), for
# sensitivity studies; give such runs their own OUT.
MATERIALS ?= $(if $(VARIANT),$(ROOT)/workflows/materials/$(VARIANT).json)
ifneq ($(VARIANT),)
ifeq ($(wildcard $(MATERIALS)),)
$(error VARIANT=$(VARIANT): $(MATERIALS) does not exist (the variants: workflows/materials/*.json))
endif
endif
MATERIALS_FLAG := $(if $(MATERIALS),--materials $(abspath $(MATERIALS)))

# After each case: done, left and the time to go (hvi-validate progress), with the -j of this
# make (in MAKEFLAGS once make runs the recipes; 1 without -j).
JOBS = $(or $(patsubst -j%,%,$(filter -j%,$(MAKEFLAGS))),1)
AFTER_VERDICT = @$(HVI_VALIDATE) progress --set $(SET) --out-dir $(OUT) --jobs $(JOBS)

# The verdicts kept in the repository, one file per case and spacing: a verdict found there
# stands for its run (the run is not repeated), so a validation spans sessions and machines
# and docs/validation.md can be regenerated without the run files. `make validate-keep`
# copies the verdicts of OUT there. They hold for the solver that made them (their
# provenance names its version): after a change to the physics, `make validate-forget` and
# run again.
ARCHIVE ?= $(ROOT)/data/validation/$(if $(VARIANT),sensitivity/$(VARIANT),verdicts)/$(RESOLUTION)

# The kept verdicts of the other spacings: the report's verdict-stability table, its columns
# from coarse to fine (the spacings' names sorted, then reversed: 0.04 before 0.02).
reverse = $(if $(1),$(call reverse,$(wordlist 2,$(words $(1)),$(1))) $(firstword $(1)))
OTHER_KEPT := $(call reverse,$(sort $(filter-out $(ARCHIVE) $(ROOT)/data/validation/verdicts/$(RESOLUTION),$(wildcard $(ROOT)/data/validation/verdicts/*))))
# And the kept verdicts of the sensitivity studies at this spacing, in the default library's
# report only.
VARIANTS_KEPT := $(sort $(wildcard $(ROOT)/data/validation/sensitivity/*/$(RESOLUTION)))
COMPARE_FLAGS := $(if $(VARIANT),,$(foreach d,$(OTHER_KEPT),--compare-kept $(d)) \
  $(foreach d,$(VARIANTS_KEPT),--sensitivity-kept $(d)))

.PHONY: validate validate-ble validate-keep validate-forget slurm-validate
# Keep each case's inputs, scene and run file (not .SECONDARY for everything: that makes
# every target intermediate, and a verdict missing under a newer report was never made).
.PRECIOUS: $(OUT)/%/panel.json $(OUT)/%/scene.json $(OUT)/%/run.h5
.DELETE_ON_ERROR:

validate: $(REPORT)

# The report without running anything (seconds for every case): the equations' verdicts,
# the kept ones of the hydrocode (ARCHIVE, below), and "not run" for the rest.
KEPT_VERDICTS = $(foreach c,$(CASES),$(if $(wildcard $(ARCHIVE)/$(c).json),$(OUT)/$(c)/verdict.json))
validate-ble: $(foreach c,$(CASES),$(OUT)/$(c)/ble.json) $(KEPT_VERDICTS)
	$(HVI_VALIDATE) report --set $(SET) --out-dir $(OUT) --resolution-mm $(RESOLUTION) \
	  $(COMPARE_FLAGS) -o $(REPORT)
	@echo "validate-ble: $(words $(CASES)) cases -> $(REPORT)"

$(REPORT): $(foreach c,$(CASES),$(OUT)/$(c)/verdict.json $(OUT)/$(c)/ble.json)
	$(HVI_VALIDATE) report --set $(SET) --out-dir $(OUT) --resolution-mm $(RESOLUTION) \
	  $(COMPARE_FLAGS) -o $@
	@echo "validate: $(words $(CASES)) cases -> $@"

# Kept with the paths inside them relative to the repository (no machine's path in the files).
validate-keep:
	@mkdir -p $(ARCHIVE); n=0; for c in $(CASES); do \
	  v=$(OUT)/$$c/verdict.json; [ -f $$v ] || continue; \
	  sed 's|$(ROOT)/||g' $$v > $(ARCHIVE)/$$c.json.tmp; touch -r $$v $(ARCHIVE)/$$c.json.tmp; \
	  if cmp -s $(ARCHIVE)/$$c.json.tmp $(ARCHIVE)/$$c.json; then rm $(ARCHIVE)/$$c.json.tmp; \
	  else mv $(ARCHIVE)/$$c.json.tmp $(ARCHIVE)/$$c.json; n=$$((n+1)); fi; done; \
	echo "validate-keep: $$n new verdicts -> $(ARCHIVE)"

# The cases as a Slurm job array (slurm.mk), the report by the collect job.
slurm-validate:
	$(call slurm_array,$(OUT)/slurm/validate.sbatch,hvi-validate,$(foreach \
	  c,$(CASES),$(OUT)/$(c)/verdict.json),validate.mk,SET=$(SET) RESOLUTION=$(RESOLUTION) \
	  BIN=$(BIN) OUT=$(OUT) REPORT=$(REPORT) ARCHIVE=$(ARCHIVE) $(if $(MATERIALS),MATERIALS=$(abspath \
	  $(MATERIALS))) $(if $(VARIANT),VARIANT=$(VARIANT)) $(if $(strip \
	  $(ONLY_CASES)),ONLY_CASES="$(strip $(ONLY_CASES))") $(if \
	  $(END_TIME_US),END_TIME_US=$(END_TIME_US)),validate)

validate-forget:
	rm -f $(foreach c,$(CASES),$(ARCHIVE)/$(c).json)

ifeq ($(CASE_CHAIN),)
# One job per case: a sub-make of the case's whole chain (kept verdict, or inputs -> scene ->
# run -> verdict). A single make with -j queues every runnable job of the tree in order, so
# every case's run would go before the first verdict and a validation stopped part-way would
# have none. A verdict that exists stands (as a kept one does); delete it to redo the case.
$(foreach c,$(CASES),$(OUT)/$(c)/verdict.json): $(OUT)/%/verdict.json:
	@$(MAKE) --no-print-directory -f $(VALIDATE_MK) CASE_CHAIN=1 $@
else
# Before the run rules: a kept verdict, where there is one, is taken instead of a run.
$(OUT)/%/verdict.json: $(ARCHIVE)/%.json
	@mkdir -p $(@D); cp -p $< $@
endif

$(OUT)/%/panel.json:
	$(HVI_VALIDATE) inputs $* --out-dir $(OUT)/$* -q

$(OUT)/%/ble.json: $(OUT)/%/panel.json
	$(BIN)/ble-size/ble-size $(OUT)/$*/constraints.json -o $@ 2>$(OUT)/$*/ble.log

include $(ROOT)/workflows/run-rules.mk
include $(ROOT)/workflows/slurm.mk
