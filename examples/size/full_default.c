/* SPDX-License-Identifier: MIT */
/*
 * full_default.c: program kind "the full default": the full scene with the
 * default model, so both default tables (earthshine, atmosphere) are linked.
 */
#include "scene.h"

int main(void)
{
    return size_full_scene(NULL);
}
