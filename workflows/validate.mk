# make validate: the verdicts of the validation cases against the tests (docs/validation.md).
ROOT := $(abspath $(dir $(lastword $(MAKEFILE_LIST)))/..)
BIN ?= $(ROOT)/build/tools
SET ?= quick
RESOLUTION ?= 0.04
THREADS ?= 1
END_TIME_US ?=
# One directory per spacing, shared by the sets: a case run for one set counts for all.
# Relative OUT and REPORT are taken from the repository root (make -C changes directory).
OUT ?= out/validate/$(RESOLUTION)
REPORT ?= $(OUT)/validation.md
override OUT := $(if $(filter /%,$(OUT)),$(OUT),$(ROOT)/$(OUT))
override REPORT := $(if $(filter /%,$(REPORT)),$(REPORT),$(ROOT)/$(REPORT))

HVI_VALIDATE := $(BIN)/hvi-validate/hvi-validate
CASES := $(shell $(HVI_VALIDATE) list --set $(SET))
ifeq ($(strip $(CASES)),)
$(error hvi-validate listed no case for SET=$(SET): build the toolkit first (scripts/build.sh))
endif
END_TIME_FLAG := $(if $(END_TIME_US),--end-time-us $(END_TIME_US))
# MATERIALS=FILE: a material library laid over the built-in one (hvi-run --materials), for
# sensitivity studies; give such runs their own OUT.
MATERIALS ?=
MATERIALS_FLAG := $(if $(MATERIALS),--materials $(abspath $(MATERIALS)))

# After each case: done, left and the time to go (hvi-validate progress), with the -j of this
# make (in MAKEFLAGS once make runs the recipes; 1 without -j).
JOBS = $(or $(patsubst -j%,%,$(filter -j%,$(MAKEFLAGS))),1)
AFTER_VERDICT = @$(HVI_VALIDATE) progress --set $(SET) --out-dir $(OUT) --jobs $(JOBS)

.PHONY: validate validate-ble
.SECONDARY:
.DELETE_ON_ERROR:

validate: $(REPORT)

# The equations' verdicts alone (seconds for every case); the hydrocode columns of cases not
# run yet say so.
validate-ble: $(foreach c,$(CASES),$(OUT)/$(c)/ble.json)
	$(HVI_VALIDATE) report --set $(SET) --out-dir $(OUT) --resolution-mm $(RESOLUTION) -o $(REPORT)
	@echo "validate-ble: $(words $(CASES)) cases -> $(REPORT)"

$(REPORT): $(foreach c,$(CASES),$(OUT)/$(c)/verdict.json $(OUT)/$(c)/ble.json)
	$(HVI_VALIDATE) report --set $(SET) --out-dir $(OUT) --resolution-mm $(RESOLUTION) -o $@
	@echo "validate: $(words $(CASES)) cases -> $@"

$(OUT)/%/panel.json:
	$(HVI_VALIDATE) inputs $* --out-dir $(OUT)/$* -q

$(OUT)/%/ble.json: $(OUT)/%/panel.json
	$(BIN)/ble-size/ble-size $(OUT)/$*/constraints.json -o $@ 2>$(OUT)/$*/ble.log

include $(ROOT)/workflows/run-rules.mk
