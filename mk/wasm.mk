# SPDX-License-Identifier: MIT
# mk/wasm.mk: the runtime in WebAssembly and the browser viewer (docs/viewer.md).
#   make wasm          build/wasm/orbillum.wasm (double precision, the same src/ and tables/)
#                      and its JavaScript module build/wasm/orbillum.js
#   make test-wasm     the wasm module against the native build, bit for bit: the shipped
#                      cases (through the JavaScript module, vs build/oi-plan --csv) and every
#                      double-precision stability vector (the same evaluators, both builds; and
#                      through the JavaScript module); the page's picture against the runtime's flux;
#                      the planner's CSV reader over a text in memory against it over a file
#   make viewer        build/viewer/: the static page (three.js bundled, no network at run time)
#   make test-viewer   the page in headless Chromium (Playwright); skips, saying so, when no
#                      browser can be installed
#   make viewer-shots  three screenshots of the page into docs/viewer/
# Toolchain: Debian's clang, lld, wasi-libc (its libm: exp, log, log10, pow) and
# libclang-rt-14-dev-wasm32, installed by `make wasm-deps` when missing.

WASM_CC ?= clang
WASM_DIR := $(BUILDDIR)/wasm
VIEWER_DIR := $(BUILDDIR)/viewer
WASM_TARGET := --target=wasm32-wasi
# log10 in glibc's form (web/wasm/oi_wasm_math.c says why), through the runtime's port hook.
WASM_MATH := -include web/wasm/oi_wasm_math.h -DOI_LOG10=oi_wasm_log10
WASM_CFLAGS := $(WASM_TARGET) $(WARN) $(OPT) $(RT_MATH) -ffunction-sections -fdata-sections \
  $(WASM_MATH) -Iinclude -Isrc -Itables -Iplanner
# The planner's row rules, its CSV reader (over a text in memory) and its rows' text: the very
# files build/oi-plan compiles (docs/viewer.md), for planCsv (web/wasm/plan_wasm.c).
WASM_PLAN_SRC := planner/rows.c planner/csv_read.c planner/csv_mem.c planner/output_text.c \
  planner/numtext.c planner/shapes_find.c
WASM_SRC := $(RT_SRC) $(WASM_PLAN_SRC) \
  web/wasm/oi_wasm.c web/wasm/oi_wasm_math.c web/wasm/plan_wasm.c
WASM_OBJ := $(patsubst %.c,$(WASM_DIR)/obj/%.o,$(WASM_SRC))
# What JavaScript calls: the public API (include/orbillum.h) and web/wasm/oi_wasm.c.
WASM_EXPORTS := oi_status_name oi_lambert_phase oi_angle oi_cap_overlap oi_sun_fraction \
  oi_earthshine oi_moon_phase_law oi_scene_defaults oi_illuminate oi_magnitude_v \
  oi_flux_from_magnitude oi_camera_builtin oi_camera_find oi_flag_name oi_expose oi_expose_scene \
  oi_shape_check oi_shape_builtin oi_shape_find oi_facet_brdf oi_earthshine_plate \
  oi_skylight oi_sun_fraction_batch oi_earthshine_batch oi_illuminate_batch \
  oi_illuminate_batch_outputs oi_expose_batch oi_expose_scene_batch oi_expose_batch_outputs \
  oi_expose_scene_batch_outputs \
  oi_wasm_scratch oi_wasm_scratch_bytes oi_wasm_layout_count oi_wasm_layout_name oi_wasm_layout_value \
  oi_plan_wasm_text oi_plan_wasm_records oi_plan_wasm_record oi_plan_wasm_nfields \
  oi_plan_wasm_field oi_plan_wasm_open oi_plan_wasm_notes oi_plan_wasm_next oi_plan_wasm_finish \
  oi_plan_wasm_row_int oi_plan_wasm_row_ptr oi_plan_wasm_csv_header
WASM_COMMA := ,
WASM_LDFLAGS := $(WASM_TARGET) -nostartfiles -Wl,--no-entry -Wl,--gc-sections \
  $(addprefix -Wl$(WASM_COMMA)--export=,$(WASM_EXPORTS))
WASM_MODULE := $(WASM_DIR)/orbillum.wasm
WASM_JS := $(WASM_DIR)/orbillum.js
STAB_DUMP_SRC := web/wasm/stab_dump.c
NODE ?= node
NPM ?= npm
NPM_DIR := $(BUILDDIR)/npm
VIEWER_VENV := $(BUILDDIR)/viewer-venv
VIEWER_PY := $(VIEWER_VENV)/bin/python
CHROMIUM ?= /usr/bin/chromium

.PHONY: wasm wasm-deps test-wasm viewer viewer-deps test-viewer viewer-shots browser-deps

wasm: $(WASM_MODULE) $(WASM_JS) ## the runtime as a wasm32 module with its JavaScript module (build/wasm/)

# A probe that compiles and links a wasm32 program with libm tells whether the toolchain is there.
wasm-deps: $(WASM_DIR)/.deps
$(WASM_DIR)/.deps:
	@mkdir -p $(WASM_DIR)
	@if ! printf '#include <math.h>\ndouble f(double x);\ndouble f(double x){return exp(x);}\n' \
	    | $(WASM_CC) $(WASM_TARGET) -O2 -nostartfiles -Wl,--no-entry -Wl,--export=f -x c - \
	      -o $(WASM_DIR)/probe.wasm >/dev/null 2>&1; then \
	  echo "installing clang, lld, wasi-libc, libclang-rt-14-dev-wasm32 (Debian)"; \
	  $(APT_GET) clang lld wasi-libc libclang-rt-14-dev-wasm32; \
	fi
	@rm -f $(WASM_DIR)/probe.wasm
	@touch $@

$(WASM_DIR)/obj/%.o: %.c mk/wasm.mk | $(WASM_DIR)/.deps
	@mkdir -p $(dir $@)
	$(WASM_CC) $(WASM_CFLAGS) -MMD -MP -c $< -o $@

# The planner's number text falls back on libc's snprintf and strtod in rare cases: wasi-libc's
# full printf and scanf (long double) keep them free of stderr, so the module still imports nothing.
$(WASM_MODULE): $(WASM_OBJ) mk/wasm.mk
	$(WASM_CC) $(WASM_LDFLAGS) $(WASM_OBJ) -lc-printscan-long-double -lm -o $@

$(WASM_JS): web/src/orbillum.js
	@mkdir -p $(dir $@)
	cp $< $@

# The stability dump, natively (against build/liborbillum.a) and as a WASI program.
$(WASM_DIR)/stab_dump: $(STAB_DUMP_SRC) $(LIB_double) $(wildcard tests/stability/*.h)
	@mkdir -p $(dir $@)
	$(CC) $(TEST_CFLAGS) -Itests $< $(LIB_double) -lm -o $@

$(WASM_DIR)/stab_dump.wasm: $(STAB_DUMP_SRC) $(WASM_OBJ) $(wildcard tests/stability/*.h)
	$(WASM_CC) $(WASM_TARGET) -std=c99 -Wall -Wextra -Wpedantic -Wshadow -Werror -O1 \
	  -Iinclude -Isrc -Itables -Itests $(STAB_DUMP_SRC) \
	  $(WASM_OBJ) -lm -o $@

test-wasm: wasm $(PLAN) $(WASM_DIR)/stab_dump $(WASM_DIR)/stab_dump.wasm ## wasm vs native, bit for bit
	$(NODE) --test tests/browser/test_wasm.mjs tests/browser/test_render.mjs

# ---- the page
$(NPM_DIR)/.deps: web/package.json web/package-lock.json
	@mkdir -p $(NPM_DIR)
	cp web/package.json web/package-lock.json $(NPM_DIR)/
	cd $(NPM_DIR) && $(NPM) ci --no-audit --no-fund --loglevel=error
	@touch $@

viewer: wasm $(NPM_DIR)/.deps ## the browser viewer, static, offline (build/viewer/index.html)
	$(NODE) web/tools/build.mjs --npm $(NPM_DIR)/node_modules --wasm $(WASM_MODULE) \
	  --out $(VIEWER_DIR)

# Chromium from Debian and Playwright for Python (pinned, web/requirements-viewer.txt), which
# drives the system browser: it downloads none of its own.
browser-deps: $(VIEWER_VENV)/.deps
$(VIEWER_VENV)/.deps: web/requirements-viewer.txt
	@if [ ! -x $(CHROMIUM) ]; then \
	  echo "installing chromium (Debian)"; \
	  { $(APT_GET) chromium; } || echo "chromium could not be installed"; \
	fi
	@[ -x $(VIEWER_PY) ] || python3 -m venv $(VIEWER_VENV)
	$(VIEWER_PY) -m pip install -q --disable-pip-version-check -r web/requirements-viewer.txt
	@touch $@

test-viewer: viewer $(PLAN) ## the page in headless Chromium: numbers equal oi-plan's, controls act
	@$(MAKE) --no-print-directory browser-deps || true
	@if [ ! -x $(CHROMIUM) ] || ! $(VIEWER_PY) -c 'import playwright' >/dev/null 2>&1; then \
	  echo "test-viewer: SKIPPED: no browser ($(CHROMIUM)) or no Playwright could be installed"; \
	else \
	  CHROMIUM=$(CHROMIUM) VIEWER_DIR=$(VIEWER_DIR) PLAN=$(PLAN) \
	    $(VIEWER_PY) -m pytest -q tests/browser/test_viewer.py; \
	fi

viewer-shots: viewer browser-deps ## three screenshots of the viewer into docs/viewer/
	CHROMIUM=$(CHROMIUM) VIEWER_DIR=$(VIEWER_DIR) $(VIEWER_PY) tests/browser/shots.py docs/viewer

-include $(WASM_OBJ:.o=.d)
TEST_TARGETS += test-wasm test-viewer
