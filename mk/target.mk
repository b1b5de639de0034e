# SPDX-License-Identifier: MIT
# mk/target.mk: the flight target. Included by the Makefile.
#   make cross        the runtime for Cortex-M4F (float) and Cortex-M7 (double), -Os and -O2
#   make size         flash and RAM per configuration and compile-time option set
#   make stack        worst-case stack of every public function (-fstack-usage + call graph)
#   make target-test  bare-metal self-test images run under qemu-system-arm
#                     (TARGET_STRICT=1: known deviations count as failures)
#   make target-bench instructions per scene on the Cortex-M builds (qemu -icount)
# Every runtime file is compiled with the host's strict flags ($(WARN), -Werror included).
# The option sets (OPTSET_*) are defined in mk/matrix.mk, which tests each of them on the host.

CROSS_PREFIX ?= arm-none-eabi-
CROSS_CC := $(CROSS_PREFIX)gcc
CROSS_AR := $(CROSS_PREFIX)ar
QEMU ?= qemu-system-arm
QEMU_TIMEOUT ?= 60
CROSS_DIR := $(BUILDDIR)/cross
CROSS_EXTRA ?=
HOST_PY ?= python3

# Cores: flags, qemu machine and cpu.
CPU_m4f := -mthumb -mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard -DOI_SINGLE_PRECISION
CPU_m7 := -mthumb -mcpu=cortex-m7 -mfpu=fpv5-d16 -mfloat-abi=hard
MACHINE_m4f := mps2-an386
MACHINE_m7 := mps2-an500
QCPU_m4f := cortex-m4
QCPU_m7 := cortex-m7
CROSS_CORES := m4f m7
CROSS_OPTS := Os O2
CROSS_CFGS := $(foreach c,$(CROSS_CORES),$(foreach o,$(CROSS_OPTS),$(c)-$(o)))

# Compile-time option sets measured by `make size` (OPTSET_<name> in mk/matrix.mk).
CROSS_OPTSETS := full sun_only no_moon no_atmosphere no_exposure no_earth_table no_facets sun_uniform \
  no_albedo_models no_skylight
# which program each option set links (target/size_<prog>.c)
SIZEPROG_sun_only := sun
SIZEPROG_sun_uniform := sun

# Public functions: one stub each in libstubs.a (target/stubs.c), linked after the
# library so a function the library does not define yet is reported, not a link error.
OI_PUBLIC := oi_status_name oi_lambert_phase oi_angle oi_cap_overlap oi_sun_fraction \
  oi_earthshine oi_earthshine_sphere oi_moon_phase_law oi_scene_defaults oi_illuminate oi_magnitude_v \
  oi_flux_from_magnitude oi_camera_builtin oi_camera_find oi_flag_name oi_expose oi_expose_scene \
  oi_shape_check oi_shape_builtin oi_shape_find oi_facet_brdf oi_earthshine_plate
# The batch calls: measured by `make stack` too (no stubs: the bench and the
# self-test do not call them).
OI_BATCH_PUBLIC := oi_sun_fraction_batch oi_earthshine_batch oi_illuminate_batch \
  oi_illuminate_batch_outputs oi_expose_batch oi_expose_scene_batch oi_expose_batch_outputs \
  oi_expose_scene_batch_outputs

# The public functions that meet the 512-byte stack goal, held to it by `make stack`
# (a regression guard: it fails when one grows past): name on every core, name@core
# on that core's configurations. The others are reported (goal.* line).
STACK_GUARD := oi_status_name oi_lambert_phase oi_angle oi_cap_overlap oi_moon_phase_law \
  oi_scene_defaults oi_magnitude_v oi_flux_from_magnitude oi_camera_builtin oi_camera_find \
  oi_flag_name oi_shape_check oi_shape_builtin oi_shape_find oi_facet_brdf \
  oi_expose oi_earthshine@m4f oi_expose_scene@m4f oi_earthshine_plate@m4f oi_sun_fraction@m4f \
  oi_earthshine_batch@m4f oi_expose_batch_outputs@m4f

cfg_core = $(word 1,$(subst -, ,$(1)))
cfg_opt = $(word 2,$(subst -, ,$(1)))
CROSS_CFLAGS = $(WARN) -$(call cfg_opt,$(1)) $(CPU_$(call cfg_core,$(1))) \
  $(RT_MATH) -ffunction-sections -fdata-sections -fstack-usage -fcallgraph-info=su $(CROSS_EXTRA) \
  -Iinclude -Isrc -Itables
CROSS_LDFLAGS = $(CPU_$(call cfg_core,$(1))) -nostartfiles -T target/mps2.ld -Wl,--gc-sections
CROSS_LIBS := -lm -lc -lgcc
# The harness (startup, semihosting, self-test) is not the runtime: same warnings, no -fstack-usage.
HARNESS_CFLAGS = $(WARN) -$(call cfg_opt,$(1)) $(CPU_$(call cfg_core,$(1))) \
  -ffunction-sections -fdata-sections -Iinclude -Isrc -Itables -Itarget -Itests/c -Itests -I$(CROSS_DIR) \
  $(if $(TARGET_STRICT),-DOI_TARGET_STRICT)

# golden-vector groups of the self-test (target/golden_<name>.c)
GOLDEN := phase moon shadow earthshine stability
# golden vectors: -DOI_HAVE_REF_<NAME> for each committed tests/c/ref_<name>.h
REF_HEADERS := $(sort $(wildcard tests/c/ref_*.h))
REF_DEFS := $(foreach h,$(REF_HEADERS),-DOI_HAVE_$(shell echo $(basename $(notdir $(h))) | tr a-z A-Z))
# the stability suite's vectors
STAB_VECTORS := $(wildcard tests/stability/vectors.h)
REF_HEADERS += $(STAB_VECTORS)
REF_DEFS += $(if $(STAB_VECTORS),-DOI_HAVE_STABILITY_VECTORS)
REF_DEFS += $(if $(and $(STAB_VECTORS),$(shell grep -l 'stab_camera_d' $(STAB_VECTORS) 2>/dev/null)),-DOI_HAVE_STAB_CAMERA)
# the stability suite's list of known deviations, extracted from its source so
# the target applies exactly the host's list (target/golden_stability.c)
STAB_KNOWN_H := $(CROSS_DIR)/stab_known.h
$(STAB_KNOWN_H): $(wildcard tests/c/test_stability.c)
	@mkdir -p $(dir $@)
	@{ [ -f tests/c/test_stability.c ] && sed -n '/^static const known_issue KNOWN\[\] = {/,/^};/p' \
	    tests/c/test_stability.c | sed '1d;$$d'; true; } > $@

.PHONY: cross size stack target-test target-bench cross-clean

# ---- per (configuration, option set): objects and library
# $(1) = cfg, $(2) = option set; the full set lives at build/cross/<cfg>/, others in opt-<set>/
xdir = $(CROSS_DIR)/$(1)$(if $(filter full,$(2)),,/opt-$(2))

define CROSS_LIB_RULES
$(call xdir,$(1),$(2))/obj/%.o: %.c | deps-cross
	@mkdir -p $$(dir $$@)
	$$(CROSS_CC) $$(call CROSS_CFLAGS,$(1)) $$(OPTSET_$(2)) -MMD -MP -c $$< -o $$@

$(call xdir,$(1),$(2))/liborbillum.a: $(patsubst %.c,$(call xdir,$(1),$(2))/obj/%.o,$(RT_SRC))
	rm -f $$@ && $$(CROSS_AR) rcs $$@ $$^

$(call xdir,$(1),$(2))/stubs/%.o: target/stubs.c | deps-cross
	@mkdir -p $$(dir $$@)
	$$(CROSS_CC) $$(call HARNESS_CFLAGS,$(1)) $$(OPTSET_$(2)) -DSTUB_$$* -c $$< -o $$@

$(call xdir,$(1),$(2))/libstubs.a: $(patsubst %,$(call xdir,$(1),$(2))/stubs/%.o,$(OI_PUBLIC))
	rm -f $$@ && $$(CROSS_AR) rcs $$@ $$^

$(call xdir,$(1),$(2))/harness/%.o: target/%.c target/semihost.h target/check.h tests/stability/evaluators.h $(REF_HEADERS) $(STAB_KNOWN_H) | deps-cross
	@mkdir -p $$(dir $$@)
	$$(CROSS_CC) $$(call HARNESS_CFLAGS,$(1)) $$(OPTSET_$(2)) $$(REF_DEFS) -c $$< -o $$@

$(call xdir,$(1),$(2))/size.elf: $(call xdir,$(1),$(2))/harness/size_$(or $(SIZEPROG_$(2)),full).o \
    $(call xdir,$(1),$(2))/harness/startup.o $(call xdir,$(1),$(2))/harness/semihost.o \
    $(call xdir,$(1),$(2))/liborbillum.a $(call xdir,$(1),$(2))/libstubs.a target/mps2.ld
	$$(CROSS_CC) $$(call CROSS_LDFLAGS,$(1)) -Wl,-Map=$$(basename $$@).map $$(filter %.o %.a,$$^) \
	  $$(CROSS_LIBS) -o $$@

-include $(patsubst %.c,$(call xdir,$(1),$(2))/obj/%.d,$(RT_SRC))
endef
$(foreach c,$(CROSS_CFGS),$(foreach s,$(CROSS_OPTSETS),$(eval $(call CROSS_LIB_RULES,$(c),$(s)))))

# the self-test image per configuration (full option set)
define CROSS_IMG_RULES
$(CROSS_DIR)/$(1)/selftest.elf: $(CROSS_DIR)/$(1)/harness/selftest.o $(CROSS_DIR)/$(1)/harness/startup.o \
    $(patsubst %,$(CROSS_DIR)/$(1)/harness/golden_%.o,$(GOLDEN)) \
    $(CROSS_DIR)/$(1)/harness/semihost.o $(CROSS_DIR)/$(1)/liborbillum.a $(CROSS_DIR)/$(1)/libstubs.a \
    target/mps2.ld
	$$(CROSS_CC) $$(call CROSS_LDFLAGS,$(1)) -Wl,-Map=$$(basename $$@).map $$(filter %.o %.a,$$^) \
	  $$(CROSS_LIBS) -o $$@
endef
$(foreach c,$(CROSS_CFGS),$(eval $(call CROSS_IMG_RULES,$(c))))

# instructions per scene on the target (target/bench_target.c, qemu -icount)
define CROSS_TBENCH_RULES
$(CROSS_DIR)/$(1)/bench.elf: $(CROSS_DIR)/$(1)/harness/bench_target.o $(CROSS_DIR)/$(1)/harness/startup.o \
    $(CROSS_DIR)/$(1)/harness/semihost.o $(CROSS_DIR)/$(1)/liborbillum.a $(CROSS_DIR)/$(1)/libstubs.a \
    target/mps2.ld bench/scenes.h
	$$(CROSS_CC) $$(call CROSS_LDFLAGS,$(1)) -Wl,-Map=$$(basename $$@).map $$(filter %.o %.a,$$^) \
	  $$(CROSS_LIBS) -o $$@
endef
$(foreach c,$(CROSS_CFGS),$(eval $(call CROSS_TBENCH_RULES,$(c))))
TBENCH_ELFS := $(foreach c,$(CROSS_CFGS),$(CROSS_DIR)/$(c)/bench.elf)

CROSS_LIBS_FULL := $(foreach c,$(CROSS_CFGS),$(CROSS_DIR)/$(c)/liborbillum.a)
SIZE_ELFS := $(foreach c,$(CROSS_CFGS),$(foreach s,$(CROSS_OPTSETS),$(call xdir,$(c),$(s))/size.elf))
SELFTEST_ELFS := $(foreach c,$(CROSS_CFGS),$(CROSS_DIR)/$(c)/selftest.elf)

cross: $(CROSS_LIBS_FULL) ## runtime for Cortex-M4F (float) and M7 (double), -Os and -O2, -Werror
	@for l in $(CROSS_LIBS_FULL); do echo "built $$l"; done

size: $(SIZE_ELFS) ## flash and RAM per configuration and option set (Cortex-M, --gc-sections)
	@$(HOST_PY) tools/size_report.py --objdir $(CROSS_DIR) --cfgs "$(CROSS_CFGS)" --sets "$(CROSS_OPTSETS)" \
	  --nm $(CROSS_PREFIX)nm

stack: $(SIZE_ELFS) $(SELFTEST_ELFS) ## worst-case stack per public function (fails on recursion, VLA or a guarded call past 512 B; reports the goal)
	@$(HOST_PY) tools/stack_report.py --objdir $(CROSS_DIR) --cfgs "$(CROSS_CFGS)" \
	  --objdump $(CROSS_PREFIX)objdump --limit 512 --public "$(OI_PUBLIC) $(OI_BATCH_PUBLIC)" \
	  --guard "$(STACK_GUARD)"

target-test: $(SELFTEST_ELFS) ## run the golden vectors on Cortex-M4F and M7 under qemu-system-arm
	@set -e; fail=0; for c in $(CROSS_CFGS); do core=$${c%%-*}; \
	  case $$core in m4f) m=$(MACHINE_m4f); q=$(QCPU_m4f);; m7) m=$(MACHINE_m7); q=$(QCPU_m7);; esac; \
	  echo "== $$c on $$m ($$q)"; \
	  if timeout $(QEMU_TIMEOUT) $(QEMU) -machine $$m -cpu $$q -semihosting-config enable=on,target=native \
	     -nographic -monitor none -serial none -kernel $(CROSS_DIR)/$$c/selftest.elf \
	     > $(CROSS_DIR)/$$c/selftest.log 2>&1; then rc=0; else rc=$$?; fi; \
	  cat $(CROSS_DIR)/$$c/selftest.log; echo "target-test.$$c.exit $$rc status"; \
	  [ $$rc = 0 ] || fail=1; done; \
	  [ $$fail = 0 ] && echo "target-test passed" || { echo "target-test FAILED"; exit 1; }

target-bench: $(TBENCH_ELFS) ## instructions per scene on Cortex-M4F/M7 (qemu -icount, same scene mix as bench)
	@set -e; for c in $(CROSS_CFGS); do core=$${c%%-*}; \
	  case $$core in m4f) m=$(MACHINE_m4f); q=$(QCPU_m4f);; m7) m=$(MACHINE_m7); q=$(QCPU_m7);; esac; \
	  timeout $(QEMU_TIMEOUT) $(QEMU) -machine $$m -cpu $$q -icount shift=0 \
	    -semihosting-config enable=on,target=native -nographic -monitor none -serial none \
	    -kernel $(CROSS_DIR)/$$c/bench.elf 2>&1 | sed "s/^target\.[a-z]*\./target.$$c./"; done

cross-clean:
	rm -rf $(CROSS_DIR)
