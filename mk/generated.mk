# SPDX-License-Identifier: MIT
# mk/generated.mk: every committed generated file, its generator, and one rule to check them.
#
#   make regen            run every generator in place (rewrites the committed files)
#   make regen-changed    the same, only the tables and reference vectors whose inputs changed:
#                         the sha256 of a generator's inputs (its Python files, data files and
#                         numpy/mpmath versions, bake/common/inputs.py) differs from the one its
#                         sidecar (tables/*.json) or tests/ref/inputs.json records
#   make check-generated  copy the source tree into build/generated/, run `make regen-changed`
#                         there, and cmp every generated file with the committed one: each file
#                         that differs is named with the target that regenerates it (a table whose
#                         inputs changed differs at least in its recorded sha256)
#   make check-generated-all  the same with `make regen`: every generator runs (for a change of
#                         the generators' environment that no input names, e.g. libm, a processor)
#   make check-tables     the same check, tables only (earthshine and atmosphere)
#   make bake, bake-atm, ref-earthshine, ref-shadow, stability-vectors, golden: one generator
#
# A group <g> of GEN_GROUPS has GEN_OUT_<g> (committed files, globs allowed) and GEN_MAKE_<g>
# (the target that writes them in place). Not checked, because they are not deterministic:
# docs/performance.md (timings), docs/report.md and docs/report/*.png, docs/gallery/ (timings,
# and PNG bytes of the plotting library), docs/stability.md (errors measured through the host's
# libm, whose last bits differ between machines).

# The generators' last bits must not depend on the processor: numpy dispatches its loops to the
# widest SIMD extension the processor has (AVX-512 loops give other last bits than AVX2 ones),
# OpenBLAS picks a kernel per processor (np.dot, np.linalg.norm), and glibc's libm picks its FMA
# variants where the processor has FMA (Python's math). CI ran on a processor without AVX-512 and
# four reference files came out different. So every generator runs on the same code on any
# x86-64-v2 processor: numpy at its baseline (every dispatched extension this processor has is
# disabled, as numpy lists them), OpenBLAS's Nehalem kernel, glibc's libm without FMA, FMA4
# and AVX2.
# Only the generators' recipes get these (target-specific), never the tests or the benchmarks.
GEN_NPY_DISPATCHED := from numpy._core._multiarray_umath import __cpu_dispatch__ as d, \
  __cpu_features__ as f; print(' '.join(x for x in d if f.get(x)))
GEN_NPY_DISABLE = $(shell [ -x $(PY) ] && $(PY) -c "$(GEN_NPY_DISPATCHED)" 2>/dev/null)
GEN_TARGETS := bake bake-earth bake-atm bake-changed ref-all ref-changed ref-earthshine ref-shadow \
  stability-vectors
$(GEN_TARGETS): export NPY_DISABLE_CPU_FEATURES = $(GEN_NPY_DISABLE)
$(GEN_TARGETS): export OPENBLAS_CORETYPE := Nehalem
$(GEN_TARGETS): export GLIBC_TUNABLES := glibc.cpu.hwcaps=-AVX2,-FMA,-FMA4,-AVX512F

GEN_DIR := $(BUILDDIR)/generated
GEN_ABS_PY := $(abspath $(PY))

# The baker's command line: one command per subject (python -m bake {earthshine,atmosphere,all})
# when the package has it, else the per-table commands.
BAKE_HAS_ROOT := $(shell grep -qs -e '--root' bake/__main__.py && echo 1)
REF_GENERATE := $(wildcard tests/ref/generate.py)

ifeq ($(BAKE_HAS_ROOT),1)
GEN_OUT_tables = $(shell $(PY) -m bake all --list 2>/dev/null)
GEN_MAKE_tables := bake
bake: deps-py
	$(PY) -m bake all --root .
bake-atm: deps-py
	$(PY) -m bake atmosphere --root .
bake-changed: deps-py
	$(PY) -m bake all --changed --root .
else
GEN_OUT_tables := tables/oi_earth_* tables/oi_atm_table.c tables/oi_atm_table.h tables/oi_atm_table.json \
  tests/c/ref_atmosphere.h
GEN_MAKE_tables := bake
bake: bake-earth bake-atm
bake-earth: deps-py
	$(PY) -m bake --all --out tables $(BAKE_FLAGS)
bake-atm: deps-py
	$(PY) -m bake.atm_table --out tables --vectors tests/c/ref_atmosphere.h
endif
BAKE_FLAGS ?=

ifneq ($(REF_GENERATE),)
GEN_OUT_refs = $(shell $(PY) tests/ref/generate.py all --list 2>/dev/null) tests/ref/inputs.json
GEN_MAKE_refs := ref-all
ref-all: deps-py
	$(PY) tests/ref/generate.py all --root .
ref-changed: deps-py
	$(PY) tests/ref/generate.py all --changed --root .
ref-earthshine: deps-py
	$(PY) tests/ref/generate.py earthshine --root .
ref-shadow: deps-py
	$(PY) tests/ref/generate.py shadow --root .
stability-vectors: deps-py
	$(PY) tests/ref/generate.py stability --root .
GEN_GROUPS := tables refs golden
else
GEN_OUT_ref_earthshine := tests/c/ref_earthshine.h
GEN_MAKE_ref_earthshine := ref-earthshine
GEN_OUT_ref_shadow := tests/c/ref_phase.h tests/c/ref_shadow.h
GEN_MAKE_ref_shadow := ref-shadow
GEN_OUT_stability := tests/stability/vectors.h
GEN_MAKE_stability := stability-vectors
ref-all: ref-earthshine ref-shadow stability-vectors
ref-earthshine: deps-py
	$(PY) -m bake.gen_test_vectors
ref-shadow: deps-py
	$(PY) tests/ref/gen_refs.py
stability-vectors: deps-py
	$(PY) tests/stability/gen_vectors.py
GEN_GROUPS := tables ref_earthshine ref_shadow stability golden
endif


# what each generator target does, whichever command line the generators have
bake: ## regenerate every baked table (tables/) and its sidecars, byte for byte
bake-atm: ## regenerate the atmosphere table only
ref-all: ## regenerate every C reference vector (the shadow ones take ~6 min)
ref-earthshine: ## regenerate tests/c/ref_earthshine.h
ref-shadow: ## regenerate tests/c/ref_phase.h and ref_shadow.h (mpmath, ~6 min)
stability-vectors: ## regenerate tests/stability/vectors.h (mpmath)

# The planner's exact output on the shipped cases and the built-in scenario (mk/report.mk).
GEN_OUT_golden := tests/golden/*.plan.csv tests/golden/demo.txt
GEN_MAKE_golden := golden

.PHONY: regen regen-changed check-generated check-generated-all bake-changed ref-changed check-tables check-tables-atm check-ref-shadow bake bake-earth \
  bake-atm ref-all ref-earthshine ref-shadow stability-vectors gen-tree

# The tables first: reference vectors and golden outputs are computed from them.
regen: ## run every generator in place: tables, reference vectors, golden outputs
	$(MAKE) --no-print-directory $(GEN_MAKE_tables)
	$(MAKE) --no-print-directory $(filter-out $(GEN_MAKE_tables),$(foreach g,$(GEN_GROUPS),$(GEN_MAKE_$(g))))

# Only what changed: the tables, then the reference vectors (some read the tables), then the
# golden outputs (the planner's, fast: always).
regen-changed: ## run in place only the generators whose inputs changed (sha256 in the sidecars), then golden
	$(MAKE) --no-print-directory $(if $(BAKE_HAS_ROOT),bake-changed,$(GEN_MAKE_tables))
	$(MAKE) --no-print-directory $(if $(REF_GENERATE),ref-changed,$(GEN_MAKE_ref_earthshine) \
	  $(GEN_MAKE_ref_shadow) $(GEN_MAKE_stability)) $(GEN_MAKE_golden)

# The copy: every file git tracks or would track (not build/, not .venv), as it is now
# (outside a git checkout: every file but build/, the venv and .git).
gen-tree: deps-py
	@rm -rf $(GEN_DIR) && mkdir -p $(GEN_DIR)
	@{ if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then \
	     git ls-files -z --cached --others --exclude-standard; \
	   else find . \( -path ./build -o -path ./$(BUILDDIR) -o -path ./$(VENV) -o -path ./.git \) -prune \
	     -o -type f -print0; fi; } | xargs -0 sh -c \
	  'for f; do [ -e "$$f" ] && printf "%s\0" "$$f"; done' sh | tar --null -T - -cf - | tar -xf - -C $(GEN_DIR)
	@echo "gen-tree: source tree copied into $(GEN_DIR)"

# gen_case(group): the shell case that sets the group's outputs and regenerating command.
gen_case = $(1)) outs='$(GEN_OUT_$(1))'; how='make $(GEN_MAKE_$(1))';;

# gen_check(groups, targets): run the targets in the copy (same venv), then cmp every output
# of each group, both ways (a committed file the generator no longer writes, a new output
# that is not committed).
define gen_check
	+$(MAKE) --no-print-directory -C $(GEN_DIR) VENV=$(abspath $(VENV)) BUILDDIR=build $(2)
	@fail=0; for g in $(1); do \
	  case $$g in $(foreach g,$(GEN_GROUPS),$(call gen_case,$(g))) esac; \
	  files=$$( { (for p in $$outs; do [ -e "$$p" ] && echo "$$p"; done); \
	              (cd $(GEN_DIR) && for p in $$outs; do [ -e "$$p" ] && echo "$$p"; done); } | sort -u); \
	  [ -n "$$files" ] || { echo "check-generated: group $$g has no files"; fail=1; }; \
	  for f in $$files; do \
	    if [ ! -e $(GEN_DIR)/$$f ]; then echo "DIFF $$f: committed, but '$$how' no longer writes it"; fail=1; \
	    elif [ ! -e $$f ]; then echo "DIFF $$f: written by '$$how', not committed"; fail=1; \
	    elif ! cmp -s $$f $(GEN_DIR)/$$f; then echo "DIFF $$f differs from a fresh run: regenerate with '$$how'"; fail=1; \
	    else echo "same $$f"; fi; \
	  done; \
	done; \
	if [ $$fail = 0 ]; then echo "check-generated: every file of $(1) matches a fresh run byte for byte"; \
	else echo "check-generated: FAILED (fresh files in $(GEN_DIR))"; exit 1; fi
endef

check-generated: gen-tree ## regenerate in build/generated/ what changed (inputs' sha256), cmp every generated file
	$(call gen_check,$(GEN_GROUPS),regen-changed)

check-generated-all: gen-tree ## re-create every committed generated file in build/generated/ and cmp it (~25 min)
	$(call gen_check,$(GEN_GROUPS),regen)

check-tables: gen-tree ## re-bake every table into build/generated/ and fail on any difference with tables/
	$(call gen_check,tables,bake)

check-tables-atm: check-tables ## the same check as check-tables (the atmosphere table is one of them)

check-ref-shadow: gen-tree ## regenerate the phase/shadow references in build/generated/ and fail on any difference
	$(call gen_check,$(if $(REF_GENERATE),refs,ref_shadow),$(if $(REF_GENERATE),ref-all,ref-shadow))
