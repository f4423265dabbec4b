# The three steps every case directory goes through, shared by validate.mk and sweep.mk:
#   DIR/panel.json + DIR/writer -> DIR/scene.json -> DIR/run.h5 -> DIR/verdict.json
# under $(OUT). Set before including: OUT, BIN, RESOLUTION, THREADS; optional END_TIME_FLAG,
# MATERIALS_FLAG, and LAUNCH (a command put in front of every hvi-run, e.g. 'srun -n1 -c8');
# RUN_FLAGS and ASSESS_FLAGS replace hvi-run's and hvi-assess's -q (design.mk: progress on
# the terminal, pictures and the test's result); WRITER_FLAGS go to the scene writer; and
# spacing_of, a function of the case directory's name, gives its spacing (convergence.mk:
# one per directory; otherwise RESOLUTION).
LAUNCH ?=
WRITER_FLAGS ?=
spacing_of ?= $(RESOLUTION)
RUN_FLAGS ?= -q
ASSESS_FLAGS ?= -q

$(OUT)/%/scene.json: $(OUT)/%/panel.json
	w=$$(cat $(OUT)/$*/writer); $(BIN)/$$w/$$w $< --particle-spacing-mm $(call spacing_of,$*) \
	  $(END_TIME_FLAG) $(WRITER_FLAGS) -o $@ 2>$(OUT)/$*/scene.log

# The run writes run.part.h5, renamed to run.h5 once complete: an interrupted run leaves
# its checkpoint beside run.part.h5 (stopped by a signal) or beside the run.part.h5.tmp.PID
# a run killed outright leaves (make deletes only the target), and the next make resumes it
# with the history it already has, rather than restarting.
$(OUT)/%/run.h5: $(OUT)/%/scene.json
	@set -e; start=$$(date +%s); part=$(OUT)/$*/run.part.h5; \
	resume=$$([ -f $(OUT)/$*/run.part.ckpt.h5 ] && echo --resume || true); \
	$(LAUNCH) $(BIN)/hvi-run/hvi-run $< -o $$part --threads $(THREADS) $(MATERIALS_FLAG) $(RUN_FLAGS) $$resume; \
	mv -f $$part $@; \
	if [ -f $(OUT)/$*/run.part.xmf ]; then \
	  sed 's/run\.part\.h5/run.h5/g' $(OUT)/$*/run.part.xmf > $(OUT)/$*/run.xmf; \
	  rm -f $(OUT)/$*/run.part.xmf; fi; \
	if [ -f $(OUT)/$*/run.part.msh ]; then mv -f $(OUT)/$*/run.part.msh $(OUT)/$*/run.msh; fi; \
	echo "$*: run in $$(( $$(date +%s) - start )) s"

# AFTER_VERDICT (optional): a command run once a case's verdict is written (validate.mk: the
# progress line).
$(OUT)/%/verdict.json: $(OUT)/%/run.h5
	$(BIN)/hvi-assess/hvi-assess $< -o $@ $(ASSESS_FLAGS) 2>$(OUT)/$*/assess.log \
	  || [ $$? -eq 1 ] # 1: the verdict is written and disagrees with an --expect'ed test
	$(AFTER_VERDICT)
