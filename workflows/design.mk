# make design: the source study's design workflow (its Figure 5.1) as file targets, for one
# shield given as ble-size constraints:
#
#   CONSTRAINTS -ble-size-> sizing.json -foam2layers | hcomb2rings-> scene.json
#               -hvi-run-> run.h5 -hvi-assess-> verdict.json (+ pictures/)
#
# in OUT/NAME/. The scene writer follows the shield (hcomb2rings for a honeycomb panel, whose
# constraints then also give cell_size_mm and foil_thickness_mm; foam2layers for foam panels,
# Whipple shields and single walls). An interrupted run resumes from its checkpoint, and a
# failed step leaves no target behind (run-rules.mk).
#
#   make -C workflows design [CONSTRAINTS=file.json] [NAME=name] [RESOLUTION=0.04]
#        [THREADS=nproc] [END_TIME_US=t] [OUT=out/design] [EXPECT=tests.json]
#
# Without CONSTRAINTS: the built-in default case (workflows/default/constraints.json, the
# source study's HITF03147-2), NAME default, its verdict compared with the test's. Relative
# CONSTRAINTS, EXPECT and OUT are taken from the repository root (make -C changes directory).
ROOT := $(abspath $(dir $(lastword $(MAKEFILE_LIST)))/..)
BIN ?= $(ROOT)/build/tools
from_root = $(if $(filter /%,$(1)),$(1),$(ROOT)/$(1))

DEFAULT_CONSTRAINTS := $(ROOT)/workflows/default/constraints.json
CONSTRAINTS ?= $(DEFAULT_CONSTRAINTS)
override CONSTRAINTS := $(call from_root,$(CONSTRAINTS))
NAME ?= $(if $(filter $(DEFAULT_CONSTRAINTS),$(CONSTRAINTS)),default,$(basename $(notdir $(CONSTRAINTS))))
RESOLUTION ?= 0.04
THREADS ?= $(shell nproc 2>/dev/null || echo 1)
END_TIME_US ?=
OUT ?= out/design
override OUT := $(call from_root,$(OUT))
DIR := $(OUT)/$(NAME)

# The test data the picture and the verdict are set beside: the source study's cases for the
# default case (its id is the constraints' id), nothing otherwise unless EXPECT is given.
TESTS := $(ROOT)/data/validation/thesis_cases.json
EXPECT ?= $(if $(filter $(DEFAULT_CONSTRAINTS),$(CONSTRAINTS)),$(TESTS))
CASE_ID = $(shell sed -n 's/^ *"id": *"\([^"]*\)".*/\1/p' $(CONSTRAINTS) | head -n1)

END_TIME_FLAG := $(if $(END_TIME_US),--end-time-us $(END_TIME_US))
RUN_FLAGS :=
ASSESS_FLAGS = --pictures $(OUT)/$*/pictures \
               $(if $(EXPECT),--expect $(call from_root,$(EXPECT)) --case $(CASE_ID))

.PHONY: design
.SECONDARY:
.DELETE_ON_ERROR:

design: $(DIR)/verdict.json
	@cat $(DIR)/assess.log
	@echo "design: outputs in $(DIR)"

$(DIR)/sizing.json: $(CONSTRAINTS)
	@mkdir -p $(@D)
	$(BIN)/ble-size/ble-size $< -o $@ --curve $(DIR)/ballistic_limit.csv \
	  --plot $(DIR)/ballistic_limit.svg --overlay $(TESTS)

# The scene writer's input is the sizing file itself (both writers read ble-size's panel
# block); the name "honeycomb_sandwich" occurs in a sizing file only for a honeycomb shield.
$(DIR)/panel.json: $(DIR)/sizing.json
	if grep -q '"honeycomb_sandwich"' $<; then echo hcomb2rings; else echo foam2layers; fi \
	  > $(DIR)/writer
	cp $< $@

include $(ROOT)/workflows/run-rules.mk
