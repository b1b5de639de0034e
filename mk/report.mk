# SPDX-License-Identifier: MIT
# mk/report.mk: measurements and reports (writing to build/ unless a target says it refreshes docs/).
#   make report            build/report/report.md and its plots in build/report/report/ (sections:
#                          bake/report/; REPORT_ARGS: e.g. REPORT_ARGS="--only report_photon" or
#                          "--strict"); the committed docs/report.md stays as it is
#   make report-docs       the same run, written over the committed docs/report.md and docs/report/
#   make perf-doc          cross, size, stack, target-test, target-bench, binding, bench, plan-bench,
#                          the binding's callgrind count; rewrites docs/performance.md's blocks
#   make bench             host benchmark: ns and instructions per scene, against quadrature
#   make bench-peers       the Sun fraction's peers alone (numpy M&G, Orekit, Basilisk)
#   make shadow-report     planar (Montenbruck & Gill) vs exact spherical Sun fraction
#   make stability-report  the worst-error table of docs/stability.md
#   make golden            re-record the planner's golden outputs (tests/golden/)

.PHONY: report report-docs perf-doc bench bench-peers peers shadow-report stability-report golden
REPORT_ARGS ?=
REPORT_OUT := $(BUILDDIR)/report/report.md

report: deps-py ## write build/report/report.md + its plots (every number computed by this run); the tree stays clean
	MPLBACKEND=Agg $(PY) -m bake.report --out $(REPORT_OUT) $(REPORT_ARGS)

report-docs: deps-py ## the report's run, refreshing the committed docs/report.md + docs/report/*.png
	MPLBACKEND=Agg $(PY) -m bake.report --out docs/report.md $(REPORT_ARGS)

golden: $(PLAN) ## re-record tests/golden/*.plan.csv and demo.txt (only for a change meant to move them)
	@for f in tests/golden/*.in.csv; do $(PLAN) --csv $$f > $${f%.in.csv}.plan.csv || [ $$? -eq 1 ]; done
	$(PLAN) > tests/golden/demo.txt

shadow-report: deps-py ## planar Montenbruck-Gill vs exact spherical Sun fraction (regenerates refs)
	$(PY) tests/ref/gen_refs.py --only shadow --report

# ---- the worst-error table of docs/stability.md, from the stability suite
stability-report: $(BUILDDIR)/tests/double/test_stability $(BUILDDIR)/tests/float/test_stability deps-py ## rewrite the table in docs/stability.md
	BUILDDIR=$(BUILDDIR) $(PY) tests/stability/report.py

perf-doc: deps-py ## run cross size stack target-test target-bench binding bench plan-bench (tools/perf_doc.py); refresh docs/performance.md
	$(PY) tools/perf_doc.py --builddir $(BUILDDIR)

# ---- host benchmark (bench/): both precisions, static, -O2
BENCH_DIR := $(BUILDDIR)/bench
BENCH_CFLAGS := $(WARN) -O2 -g -Iinclude -Isrc -Itables

define BENCH_RULES
$(BENCH_DIR)/$(1)/stubs/%.o: target/stubs.c
	@mkdir -p $$(dir $$@)
	$$(CC) $$(BENCH_CFLAGS) $$(DEF_$(1)) -DSTUB_$$* -c $$< -o $$@

$(BENCH_DIR)/$(1)/libstubs.a: $(patsubst %,$(BENCH_DIR)/$(1)/stubs/%.o,$(OI_PUBLIC))
	rm -f $$@ && $$(AR) rcs $$@ $$^

$(BENCH_DIR)/bench-$(1): bench/bench.c bench/scenes.h $(LIB_$(1)) $(BENCH_DIR)/$(1)/libstubs.a
	$$(CC) $$(BENCH_CFLAGS) $$(DEF_$(1)) -D_POSIX_C_SOURCE=199309L bench/bench.c $(LIB_$(1)) \
	  $(BENCH_DIR)/$(1)/libstubs.a -lm $$(HOST_LDFLAGS) -o $$@
endef
$(foreach p,double float,$(eval $(call BENCH_RULES,$(p))))

bench: $(BENCH_DIR)/bench-double $(BENCH_DIR)/bench-float deps-py deps-bench ## ns and instructions per scene; table vs quadrature
	-@$(MAKE) --no-print-directory $(ILLUM_BASELINE)
	-@$(MAKE) --no-print-directory peers
	@nice -n 5 $(PY) bench/run_bench.py --bindir $(BENCH_DIR) --out $(BENCH_DIR)/bench.txt \
	  --peers $(PEERS_DIR) $$([ -x $(ILLUM_BASELINE) ] && echo --baseline $(ILLUM_BASELINE))

# ---- the Sun fraction's process peers (bench/peers.py runs them; docs/performance.md): the
# Orekit harness (bench/peers/, Maven: Orekit 12.2 from Maven Central, java 17 + mvn) and
# Basilisk in a venv of its own (bench/peers/requirements-basilisk.txt: bsk pins packages
# below requirements.lock). Each is skipped with the reason when its tools are missing.
PEERS_DIR := $(BUILDDIR)/peers
PEERS_VENV := $(BUILDDIR)/peers-venv
OREKIT_HARNESS := $(PEERS_DIR)/orekit/classpath.txt

peers: ## build the Orekit harness (java, mvn) and the Basilisk venv (build/peers-venv); a missing tool is skipped with its reason
	@if command -v java >/dev/null 2>&1 && command -v mvn >/dev/null 2>&1; then \
	  $(MAKE) --no-print-directory $(OREKIT_HARNESS); \
	else echo "peers: Orekit skipped: java or mvn not found"; fi
	@if python3 -m venv --help >/dev/null 2>&1; then \
	  $(MAKE) --no-print-directory $(PEERS_VENV)/.deps; \
	else echo "peers: Basilisk skipped: python3 -m venv not available"; fi

$(OREKIT_HARNESS): bench/peers/pom.xml $(wildcard bench/peers/src/main/java/org/orbillum/peers/*.java)
	mvn -q -B -f bench/peers/pom.xml -Dpeers.builddir=$(abspath $(PEERS_DIR))/orekit package
	@touch $@

$(PEERS_VENV)/.deps: bench/peers/requirements-basilisk.txt
	[ -x $(PEERS_VENV)/bin/python ] || python3 -m venv $(PEERS_VENV)
	$(PEERS_VENV)/bin/python -m pip install -q --disable-pip-version-check -r $<
	@touch $@

bench-peers: $(BENCH_DIR)/bench-double binding peers ## the Sun fraction's peers and the binding's cost alone, then the goals (build/bench/peers.txt)
	nice -n 5 $(PY) bench/run_bench.py --bindir $(BENCH_DIR) --out $(BENCH_DIR)/peers.txt --only-peers \
	  --peers $(PEERS_DIR)

# ---- the full illumination goal alone (instructions, double): today's scene configurations
# and the baseline below, then the goal lines (build/bench/illum.txt)
.PHONY: illum-bench
illum-bench: $(BENCH_DIR)/bench-double deps-py ## the full illumination goal: instructions per scene, today's batch against the baseline's oi_illuminate (build/bench/illum.txt)
	-@$(MAKE) --no-print-directory $(ILLUM_BASELINE)
	nice -n 5 $(PY) bench/run_bench.py --bindir $(BENCH_DIR) --out $(BENCH_DIR)/illum.txt --only-illumination \
	  $$([ -x $(ILLUM_BASELINE) ] && echo --baseline $(ILLUM_BASELINE))

# The illumination as it was before the batch interface, the baseline of the full
# illumination's speed goal: the library, tables and bench of the parent of the commit that
# added src/batch.c (now src/batch/batch.c), built with the library's flags (double) and run over the same scene mix
# (bench/scenes.h is unchanged since). Needs the git history.
ILLUM_BASELINE := $(BENCH_DIR)/illum-baseline/bench-double
$(ILLUM_BASELINE):
	@rev=$$(git log --diff-filter=A --format=%H -- src/batch.c | tail -n 1); \
	  [ -n "$$rev" ] || { echo "illum-baseline: no git history of src/batch.c"; exit 1; }; \
	  d=$(BENCH_DIR)/illum-baseline; rm -rf $$d && mkdir -p $$d && \
	  git archive "$$rev^" src include tables bench | tar -x -C $$d && \
	  $(CC) -std=c99 $(OPT) $(RT_MATH) -g -I$$d/include -I$$d/src -I$$d/tables -D_POSIX_C_SOURCE=199309L \
	    $$d/bench/bench.c $$d/src/*.c $$d/tables/*.c -lm -o $@

# ---- the catalogue planner's throughput (bench/catalog_bench.py): scenes per CPU-second per
# core (propagation, illumination apart) and the scaling from 1 to 2 local Dask workers
.PHONY: catalog-bench
catalog-bench: binding ## catalogue planner: scenes per CPU-second per core, 1 -> 2 Dask workers (build/bench/catalog.txt)
	@mkdir -p $(BENCH_DIR)
	nice -n 5 $(PY) bench/catalog_bench.py --out $(BENCH_DIR)/catalog.txt

# ---- the planner's speed (bench/plan_speed.py): oi-plan --csv rows per CPU-second on the golden
# cases repeated, output checked against the golden files; instructions per row with valgrind
.PHONY: plan-bench
plan-bench: $(PLAN) deps-py ## oi-plan --csv rows per CPU-second and instructions per row, and the ratio to the original planner (build/bench/plan.txt)
	@mkdir -p $(BENCH_DIR)
	-@$(MAKE) --no-print-directory $(PLAN_BASELINE)
	nice -n 5 $(PY) bench/plan_speed.py --plan $(PLAN) --out $(BENCH_DIR)/plan.txt \
	  $$([ -x $(PLAN_BASELINE) ] && echo --baseline $(PLAN_BASELINE))

# The original planner, the baseline of the planner's speed goal: its sources as they were
# before it had its own number text (the parent of the commit that added
# examples/oi_plan/numtext.c, where the planner then lived), built against today's library. Needs the git history.
PLAN_BASELINE := $(BUILDDIR)/plan-baseline/oi-plan
$(PLAN_BASELINE): $(LIB_double)
	@rev=$$(git log --diff-filter=A --format=%H -- examples/oi_plan/numtext.c | tail -n 1); \
	  [ -n "$$rev" ] || { echo "plan-baseline: no git history of examples/oi_plan/numtext.c"; exit 1; }; \
	  rm -rf $(BUILDDIR)/plan-baseline && mkdir -p $(BUILDDIR)/plan-baseline && \
	  git archive "$$rev^" examples/oi_plan | tar -x -C $(BUILDDIR)/plan-baseline && \
	  $(CC) -std=c99 $(OPT) -g -Iinclude -I$(BUILDDIR)/plan-baseline/examples/oi_plan \
	    $(BUILDDIR)/plan-baseline/examples/oi_plan/*.c $(LIB_double) -lm -o $@
