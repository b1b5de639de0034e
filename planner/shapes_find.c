/* SPDX-License-Identifier: MIT */
/* shapes_find.c: the target_shape lookup among a --shapes file's shapes and
 * the library's built-in ones, and the names for messages (see shapes.h);
 * without stdio, so that the viewer's WebAssembly module compiles it too. */
#include "shapes.h"

#include <string.h>

int shapes_lookup(const plan_shapes *s, const char *name, const oi_shape **out)
{
    unsigned i;
    *out = NULL;
    if (name[0] == '\0' || strcmp(name, "sphere") == 0) return 0;
    if (s != NULL) {
        for (i = 0; i < s->n_shapes; i++) {
            if (strcmp(s->shapes[i].name, name) == 0) {
                *out = &s->shapes[i].shape;
                return 0;
            }
        }
    }
    *out = oi_shape_find(name);
    return *out != NULL ? 0 : -1;
}

/* Append " name" (no blank first) to buf if it fits. */
static void add_name(char *buf, size_t size, size_t *len, const char *name)
{
    size_t n = strlen(name);
    if (*len + n + 2 > size) return;
    if (*len > 0) buf[(*len)++] = ' ';
    memcpy(buf + *len, name, n + 1);
    *len += n;
}

void shapes_names(const plan_shapes *s, char *buf, size_t size)
{
    size_t len = 0;
    unsigned i;
    int k;
    if (size == 0) return;
    buf[0] = '\0';
    add_name(buf, size, &len, "sphere");
    for (k = 0; oi_shape_builtin(k) != NULL; k++) {
        const char *name = oi_shape_builtin(k)->name;
        if (name != NULL) add_name(buf, size, &len, name);
    }
    for (i = 0; s != NULL && i < s->n_shapes; i++) add_name(buf, size, &len, s->shapes[i].name);
}
