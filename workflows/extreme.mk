# make extreme: the stiff and extreme suite (issue #25; validation/StressSuite.hpp). Every scene
# of workflows/extreme/ runs on one thread into OUT/<name>/; a run that fails is recorded
# (OUT/<name>/failed: the exit code and hvi-run's last line) rather than stopping the suite;
# REPORT tabulates how each ended, whether its fields stayed finite, its energy error, its
# smallest time step with when and what set it, and its wall time.
#
#   make -C workflows extreme [OUT=out/extreme] [REPORT=file.md] [ONLY="v07_0 v30_0"] [-j2]
# Relative OUT and REPORT are taken from the repository root.
ROOT := $(abspath $(dir $(lastword $(MAKEFILE_LIST)))/..)
BIN ?= $(ROOT)/build/tools
from_root = $(if $(filter /%,$(1)),$(1),$(ROOT)/$(1))
OUT ?= out/extreme
override OUT := $(call from_root,$(OUT))
REPORT ?= $(OUT)/extreme.md
override REPORT := $(call from_root,$(REPORT))
SCENES_DIR := $(ROOT)/workflows/extreme
NAMES := $(basename $(notdir $(wildcard $(SCENES_DIR)/*.json)))
ONLY ?=
DONE := $(foreach n,$(or $(ONLY),$(NAMES)),$(OUT)/$(n)/done)

.PHONY: extreme
.DELETE_ON_ERROR:

extreme: $(REPORT)

$(REPORT): $(DONE)
	$(BIN)/hvi-validate/hvi-validate extreme --out-dir $(OUT) -o $@
	@echo "extreme: $(words $(DONE)) cases -> $@"

$(OUT)/%/done: $(SCENES_DIR)/%.json
	@mkdir -p $(@D); rm -f $(@D)/failed $(@D)/run.h5; cp $< $(@D)/scene.json
	@cd $(@D) && $(BIN)/hvi-run/hvi-run scene.json -o run.h5 --threads 1 -q 2>run.log; \
	rc=$$?; if [ $$rc -ne 0 ]; then \
	  echo "exit $$rc: $$(tail -n1 $(@D)/run.log)" > $(@D)/failed; fi; \
	echo "extreme: $*: $$( [ $$rc -eq 0 ] && echo ok || cat $(@D)/failed)"; touch $@
