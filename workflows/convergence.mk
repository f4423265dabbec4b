# make convergence: the error-against-run-time study of one case over a ladder of particle
# spacings (the source study's particle-size study, Sec. 3.3.1, done as file targets). Each
# spacing is a case directory OUT/s<spacing>/ (run-rules.mk: inputs -> scene -> run ->
# verdict), so `make -j` runs spacings side by side and a killed make resumes; the result
# is OUT/convergence.csv, REPORT (markdown: per spacing the particles, steps, wall time,
# bumper hole, penetration depth, verdict and energy error; the observed order and
# Richardson estimate; the source study's own figures for its case) and PLOT (error against
# wall time, log-log).
#
#   make -C workflows convergence [CASE=UM-3.125] [SPACINGS="0.08 0.06 0.04 0.03 0.02 0.015"]
#        [END_TIME_US=t] [WRITER_FLAGS=...] [THREADS=1] [OUT=dir] [REPORT=file.md] [PLOT=file.png]
#   make -C workflows convergence PANEL=panel.json WRITER=foam2layers ...
#
# The default case is the source study's bumper case UM-3.125 as it ran it: 3 us (the hole
# has formed), plates cut at 10 mm radius (the hole is 6.7 mm wide). Another case runs its
# own scene (end time by the scene rule) unless END_TIME_US and WRITER_FLAGS say otherwise.
# Relative OUT, REPORT, PLOT and PANEL are taken from the repository root.
ROOT := $(abspath $(dir $(lastword $(MAKEFILE_LIST)))/..)
BIN ?= $(ROOT)/build/tools
from_root = $(if $(filter /%,$(1)),$(1),$(ROOT)/$(1))

CASE ?= $(if $(PANEL),,UM-3.125)
PANEL ?=
WRITER ?=
SPACINGS ?= 0.08 0.06 0.04 0.03 0.02 0.015
ifeq ($(CASE),UM-3.125)
END_TIME_US ?= 3
WRITER_FLAGS ?= --domain-radius-mm 10
endif
END_TIME_US ?=
WRITER_FLAGS ?=
THREADS ?= 1
NAME := $(if $(CASE),$(CASE),$(basename $(notdir $(PANEL))))
OUT ?= out/convergence/$(NAME)
override OUT := $(call from_root,$(OUT))
REPORT ?= $(OUT)/convergence.md
override REPORT := $(call from_root,$(REPORT))
PLOT ?= $(OUT)/convergence.png
override PLOT := $(call from_root,$(PLOT))
RESOLUTION := per-point
END_TIME_FLAG := $(if $(END_TIME_US),--end-time-us $(END_TIME_US))
spacing_of = $(patsubst s%,%,$(1))
SETUP := $(if $(END_TIME_US),to $(END_TIME_US) µs,to the scene rule's end time)$(if \
  $(WRITER_FLAGS), with $(WRITER_FLAGS)), $(THREADS) thread(s) a run
HVI_VALIDATE := $(BIN)/hvi-validate/hvi-validate

.PHONY: convergence
# Keep each point's inputs, scene and run file (not .SECONDARY for everything: that makes
# every target intermediate, and a point missing under a newer report was never made).
.PRECIOUS: $(OUT)/%/panel.json $(OUT)/%/scene.json $(OUT)/%/run.h5
.DELETE_ON_ERROR:

POINTS := $(foreach h,$(SPACINGS),$(OUT)/s$(h)/verdict.json)

convergence: $(REPORT)

$(REPORT): $(POINTS)
	$(HVI_VALIDATE) convergence $(CASE) --out-dir $(OUT) -o $@ --csv $(OUT)/convergence.csv \
	  --plot $(PLOT) --setup "$(SETUP)"
	@echo "convergence: $(words $(SPACINGS)) spacings -> $@, $(PLOT)"

$(OUT)/s%/panel.json:
ifneq ($(CASE),)
	$(HVI_VALIDATE) inputs $(CASE) --out-dir $(OUT)/s$* -q
else
	@mkdir -p $(@D)
	echo $(WRITER) > $(OUT)/s$*/writer
	cp $(call from_root,$(PANEL)) $@
endif

include $(ROOT)/workflows/run-rules.mk
