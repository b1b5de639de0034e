# SPDX-License-Identifier: MIT
# mk/size.mk: linked bytes per program kind (examples/size/), with
# --gc-sections, on the host and on the Cortex-M cross builds. Included by
# the Makefile; `make size` runs it (after the option-set report of the
# cross build), `make size-kinds` alone.
#   sun_noatm     oi_sun_fraction, atmosphere off, own NULL oi_atm_table_default and
#                 oi_atm_total_default
#   sun_atm       oi_sun_fraction with the default atmosphere
#   own_earth     full scene, a caller's earthshine table (oi_earth_leo), own NULL
#                 oi_earth_table_default
#   full_default  full scene, both default tables
# Checked with nm: sun_noatm holds no table symbol, own_earth no oi_earth_diffuse.

SIZE_KINDS := sun_noatm sun_atm own_earth full_default
SIZE_KIND_DIR := $(BUILDDIR)/size
SIZE_KIND_CROSS := m4f-Os m7-Os
SIZE_KIND_SRC_DEPS := examples/size/scene.h
SIZE_TABLE_SYMS := oi_earth_diffuse|oi_earth_leo|oi_earth_geo|oi_earth_angular|oi_atm_vband|oi_atm_total_q
SIZE_HOST_ELFS := $(foreach k,$(SIZE_KINDS),$(SIZE_KIND_DIR)/host/$(k))
SIZE_CROSS_ELFS := $(foreach c,$(SIZE_KIND_CROSS),$(foreach k,$(SIZE_KINDS),$(SIZE_KIND_DIR)/$(c)/$(k).elf))

.PHONY: size-kinds size-kinds-host

$(SIZE_HOST_ELFS): $(SIZE_KIND_DIR)/host/%: examples/size/%.c $(SIZE_KIND_SRC_DEPS) $(LIB_double)
	@mkdir -p $(dir $@)
	$(CC) $(HOST_CFLAGS) -ffunction-sections -fdata-sections $< $(LIB_double) -lm \
	  -Wl,--gc-sections -Wl,-Map=$@.map -o $@

define SIZE_KIND_CROSS_RULES
$(foreach k,$(SIZE_KINDS),$(SIZE_KIND_DIR)/$(1)/$(k).o): $(SIZE_KIND_DIR)/$(1)/%.o: examples/size/%.c $(SIZE_KIND_SRC_DEPS) | deps-cross
	@mkdir -p $$(dir $$@)
	$$(CROSS_CC) $$(call HARNESS_CFLAGS,$(1)) -c $$< -o $$@

$(foreach k,$(SIZE_KINDS),$(SIZE_KIND_DIR)/$(1)/$(k).elf): $(SIZE_KIND_DIR)/$(1)/%.elf: $(SIZE_KIND_DIR)/$(1)/%.o $(CROSS_DIR)/$(1)/harness/startup.o \
    $(CROSS_DIR)/$(1)/harness/semihost.o $(CROSS_DIR)/$(1)/liborbillum.a target/mps2.ld
	$$(CROSS_CC) $$(call CROSS_LDFLAGS,$(1)) -Wl,-Map=$$(basename $$@).map $$(filter %.o %.a,$$^) \
	  $$(CROSS_LIBS) -o $$@
endef
$(foreach c,$(SIZE_KIND_CROSS),$(eval $(call SIZE_KIND_CROSS_RULES,$(c))))

# nm: what a program kind must not hold ($(1) program, $(2) pattern, $(3) what)
size_nm_check = if nm $(1) | grep -Eq '$(2)'; then echo "size-kinds: $(1) links $(3):"; \
  nm $(1) | grep -E '$(2)'; exit 1; else echo "size-kinds: $(1): no $(3) (nm)"; fi

size-kinds-host: $(SIZE_HOST_ELFS) ## linked bytes per program kind on the host (--gc-sections), nm checks
	@set -e; $(call size_nm_check,$(SIZE_KIND_DIR)/host/sun_noatm,$(SIZE_TABLE_SYMS),table symbol); \
	$(call size_nm_check,$(SIZE_KIND_DIR)/host/own_earth,oi_earth_diffuse,oi_earth_diffuse)
	@$(HOST_PY) tools/size_report.py --kinds "$(SIZE_KINDS)" --kinddir $(SIZE_KIND_DIR) --kindcfgs host

size-kinds: size-kinds-host $(SIZE_CROSS_ELFS) ## linked bytes per program kind, host and Cortex-M
	@set -e; for c in $(SIZE_KIND_CROSS); do \
	  $(call size_nm_check,$(SIZE_KIND_DIR)/$$c/sun_noatm.elf,$(SIZE_TABLE_SYMS),table symbol); \
	  $(call size_nm_check,$(SIZE_KIND_DIR)/$$c/own_earth.elf,oi_earth_diffuse,oi_earth_diffuse); done
	@$(HOST_PY) tools/size_report.py --kinds "$(SIZE_KINDS)" --kinddir $(SIZE_KIND_DIR) \
	  --kindcfgs "$(SIZE_KIND_CROSS)"

size: size-kinds
