# SPDX-License-Identifier: MIT
# mk/analysis.mk: fuzzing (libFuzzer), sanitizers, static analysers.
#
#   make fuzz       each libFuzzer target for FUZZ_SECONDS (60) per precision,
#                   starting from fuzz/corpus/<target>; new crashers land in
#                   $(BUILDDIR)/fuzz/artifacts/ (copy them into fuzz/corpus/).
#   make fuzz-ci    the same, FUZZ_CI_SECONDS (15) each, after replaying the
#                   committed corpus (the regression inputs).
#   make fuzz-replay  replay the committed corpus only (no new inputs).
#   make sanitize   every C test program (both precisions) built with
#                   -fsanitize=address,undefined -fno-sanitize-recover, and run.
#   make analyze    cppcheck (three configurations), gcc -fanalyzer and clang
#                   --analyze (both precisions) on src/ and tables/: all clean.
# Each installs what it needs (clang, libclang-rt-dev, cppcheck: mk/deps.mk).

FUZZ_SECONDS ?= 60
FUZZ_CI_SECONDS ?= 15
FUZZ_CC ?= clang
FUZZ_DIR := $(BUILDDIR)/fuzz
FUZZ_SAN := -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all
# FUZZ_DEFS=-DFUZZ_STRICT: no workaround for the open findings of docs/stability.md
# (use with its own BUILDDIR, e.g. make fuzz-replay FUZZ_DEFS=-DFUZZ_STRICT BUILDDIR=build/strict)
FUZZ_DEFS ?=
FUZZ_CFLAGS := -std=c99 -g -O1 -fno-omit-frame-pointer -Iinclude -Isrc -Itables $(FUZZ_SAN) $(FUZZ_DEFS)
FUZZ_TARGETS := api csv batch
FUZZ_BINS := $(foreach t,$(FUZZ_TARGETS),$(FUZZ_DIR)/double/fuzz_$(t) $(FUZZ_DIR)/float/fuzz_$(t))
# The planner's modules except its main(): the CSV target links the reader.
PLAN_LIB_SRC := $(filter-out planner/main.c,$(PLAN_SRC))

.PHONY: fuzz fuzz-ci fuzz-replay fuzz-build sanitize analyze \
        analyze-cppcheck analyze-gcc analyze-clang

# ---- libFuzzer targets: the runtime compiled once per precision (the binary's directory) with
# the sanitizers and the fuzzer's coverage (-fsanitize=fuzzer-no-link: what -fsanitize=fuzzer
# compiles, without libFuzzer's main), linked into each target: fuzz_api and fuzz_batch on the
# runtime alone, fuzz_csv with the planner's reader.
FUZZ_PREC_double :=
FUZZ_PREC_float := -DOI_SINGLE_PRECISION
define FUZZ_RULES
$(FUZZ_DIR)/$(1)/obj/%.o: %.c | deps-fuzz
	@mkdir -p $$(dir $$@)
	$$(FUZZ_CC) $$(FUZZ_CFLAGS) $(FUZZ_PREC_$(1)) -Iplanner -fsanitize=fuzzer-no-link -MMD -MP -c $$< -o $$@
-include $(patsubst %.c,$(FUZZ_DIR)/$(1)/obj/%.d,$(RT_SRC) $(PLAN_LIB_SRC))

$(FUZZ_DIR)/$(1)/fuzz_api $(FUZZ_DIR)/$(1)/fuzz_batch: $(FUZZ_DIR)/$(1)/fuzz_%: fuzz/fuzz_%.c fuzz/fuzz_common.h $(patsubst %.c,$(FUZZ_DIR)/$(1)/obj/%.o,$(RT_SRC)) | deps-fuzz
	@mkdir -p $$(dir $$@)
	$$(FUZZ_CC) $$(FUZZ_CFLAGS) $(FUZZ_PREC_$(1)) -fsanitize=fuzzer $$< $(patsubst %.c,$(FUZZ_DIR)/$(1)/obj/%.o,$(RT_SRC)) -lm -o $$@

$(FUZZ_DIR)/$(1)/fuzz_csv: fuzz/fuzz_csv.c $(patsubst %.c,$(FUZZ_DIR)/$(1)/obj/%.o,$(PLAN_LIB_SRC) $(RT_SRC)) | deps-fuzz
	@mkdir -p $$(dir $$@)
	$$(FUZZ_CC) $$(FUZZ_CFLAGS) $(FUZZ_PREC_$(1)) -Iplanner -fsanitize=fuzzer $$< $(patsubst %.c,$(FUZZ_DIR)/$(1)/obj/%.o,$(PLAN_LIB_SRC) $(RT_SRC)) -lm -o $$@
endef
$(foreach p,double float,$(eval $(call FUZZ_RULES,$(p))))

fuzz-build: $(FUZZ_BINS) ## build the libFuzzer targets (both precisions)

# run_fuzz(seconds): replay the corpus, then fuzz into a scratch corpus seeded
# from the committed one (the committed corpus only grows by hand).
define run_fuzz
	@set -e; for b in $(FUZZ_BINS); do \
	  t=$$(basename $$b); p=$$(basename $$(dirname $$b)); \
	  c=fuzz/corpus/$$t; w=$(FUZZ_DIR)/work/$$p/$$t; a=$(FUZZ_DIR)/artifacts/$$p/; \
	  mkdir -p $$c $$w $$a; \
	  echo "== $$b: replay $$c"; \
	  $$b -runs=0 $$c >$(FUZZ_DIR)/$$p-$$t-replay.log 2>&1 \
	    || { tail -40 $(FUZZ_DIR)/$$p-$$t-replay.log; exit 1; }; \
	  if [ "$(1)" -gt 0 ]; then \
	    echo "== $$b: fuzz $(1) s"; \
	    q=; [ $$t = fuzz_csv ] && q=-close_fd_mask=2; \
	    $$b $$q -max_total_time=$(1) -timeout=10 -rss_limit_mb=1024 -max_len=4096 -print_final_stats=1 \
	      -artifact_prefix=$$a $$w $$c >$(FUZZ_DIR)/$$p-$$t.log 2>&1 \
	      || { tail -60 $(FUZZ_DIR)/$$p-$$t.log; echo "crasher saved in $$a"; exit 1; }; \
	    grep -E '^stat::number_of_executed_units|^stat::peak_rss_mb' $(FUZZ_DIR)/$$p-$$t.log | tr '\n' ' '; echo; \
	  fi; \
	done
endef

fuzz-replay: $(FUZZ_BINS) ## replay the committed fuzz corpus (regression inputs)
	$(call run_fuzz,0)

fuzz: $(FUZZ_BINS) ## run every fuzz target FUZZ_SECONDS (60) per precision
	$(call run_fuzz,$(FUZZ_SECONDS))

fuzz-ci: $(FUZZ_BINS) ## short fuzz run for CI (FUZZ_CI_SECONDS each)
	$(call run_fuzz,$(FUZZ_CI_SECONDS))

# ---- the C test suite under ASan + UBSan (a separate build tree).
SAN_CC ?= gcc
SAN_FLAGS := -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all -fno-omit-frame-pointer
sanitize: deps-c ## every C test (both precisions) under ASan and UBSan
	$(MAKE) --no-print-directory BUILDDIR=$(BUILDDIR)/san CC="$(SAN_CC) $(SAN_FLAGS)" OPT="-O1 -g" \
	  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 test-c

# ---- static analysis: cppcheck and gcc -fanalyzer, both precisions.
CPPCHECK_SUPP := tests/stability/cppcheck.supp
CPPCHECK_FLAGS := --std=c99 --enable=warning,style,performance,portability --inconclusive \
  --error-exitcode=1 --quiet --inline-suppr --suppressions-list=$(CPPCHECK_SUPP) \
  -Iinclude -Isrc -Itables --platform=unix64

# One explicit configuration per run (cppcheck then checks exactly that one):
# double, single, and every feature removed.
analyze-cppcheck: deps-analyze
	cppcheck $(CPPCHECK_FLAGS) -DOI_ANALYZE_DOUBLE $(RT_SRC)
	cppcheck $(CPPCHECK_FLAGS) -DOI_SINGLE_PRECISION $(RT_SRC)
	cppcheck $(CPPCHECK_FLAGS) -DOI_NO_MOON -DOI_NO_EXPOSURE -DOI_NO_ATMOSPHERE -DOI_NO_EARTH_TABLE $(RT_SRC)

# One target per (file, precision), so that make -j runs them side by side; each runs every time.
AN_PRECS := double single
AN_DEF_double :=
AN_DEF_single := -DOI_SINGLE_PRECISION
AN_GCC := $(foreach d,$(AN_PRECS),$(addprefix analyze-gcc/$(d)/,$(RT_SRC)))
AN_CLANG := $(foreach d,$(AN_PRECS),$(addprefix analyze-clang/$(d)/,$(RT_SRC)))
.PHONY: $(AN_GCC) $(AN_CLANG)

analyze-gcc: $(AN_GCC)
$(foreach d,$(AN_PRECS),$(filter analyze-gcc/$(d)/%,$(AN_GCC))): analyze-gcc/%:
	@d=$(AN_DEF_$(firstword $(subst /, ,$*))); f=$(patsubst $(firstword $(subst /, ,$*))/%,%,$*); \
	  echo "gcc -fanalyzer $$d $$f"; \
	  gcc $(WARN) -O2 -fanalyzer -Iinclude -Isrc -Itables $$d -c $$f -o /dev/null

# clang's static analyser too (clang is installed by deps-fuzz); any
# warning fails.
analyze-clang: $(AN_CLANG)
$(AN_CLANG): analyze-clang/%: | deps-fuzz
	@d=$(AN_DEF_$(firstword $(subst /, ,$*))); f=$(patsubst $(firstword $(subst /, ,$*))/%,%,$*); \
	  echo "clang --analyze $$d $$f"; \
	  out=$$($(FUZZ_CC) --analyze -std=c99 -Iinclude -Isrc -Itables $$d $$f -o /dev/null 2>&1); \
	  if [ -n "$$out" ]; then echo "$$out"; exit 1; fi

analyze: analyze-cppcheck analyze-gcc analyze-clang ## cppcheck, gcc -fanalyzer and clang --analyze on the runtime, must be clean
