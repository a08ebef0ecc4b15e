/* SPDX-License-Identifier: MIT */
/*
 * o3d.i: the ONE SWIG interface of the C# and Java bindings, hand-written. The classes themselves
 * (PointCloud, TriangleMesh, KDTreeFlann, ..., the options structs, the module class Library) are
 * emitted at build time from the C headers by tools/gen_swig_interface.py (the file it writes is
 * included at the end). This file holds what they rely on, the same for both languages:
 *   o3dx_in_<e>   an array argument (pointer + length; the managed array is pinned, never copied)
 *   o3dx_out_<e>  an array result (copied once into a managed array; `owned` buffers are freed)
 *   o3dx_view     a borrowed view (*_view functions): C# struct View, Java direct ByteBuffer
 *   O3DX_CHECK    a failed o3d_status jumps to `fail:`; %exception raises it as O3dException
 *                 (status + o3d_last_error_message()) after the call has released everything
 * Language typemaps: bindings/csharp/o3d_csharp.i, bindings/java/o3d_java.i.
 */
%module Library

%{
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "o3d/o3d.h"

#define O3DX_ARRAY_TYPES(e, T) \
  typedef struct { const T *p; size_t n; } o3dx_in_##e; \
  typedef struct { T *p; size_t n; int owned; } o3dx_out_##e;
O3DX_ARRAY_TYPES(f64, double)
O3DX_ARRAY_TYPES(f32, float)
O3DX_ARRAY_TYPES(i32, int32_t)
O3DX_ARRAY_TYPES(i64, int64_t)
O3DX_ARRAY_TYPES(u8, uint8_t)
typedef struct { const o3d_correspondence_checker_t *p; size_t n; } o3dx_in_o3d_correspondence_checker_t;
/* an array of handles (`const T* const* name, size_t num_name`): the generated interface declares one per T */
#define O3DX_HANDLES_TYPE(T) typedef struct { const T *const *p; size_t n; } o3dx_handles_##T;
/* a borrowed view (read-only / writable): address, rows, bytes; valid until its owner changes */
typedef struct { void *p; size_t rows; size_t bytes; } o3dx_view;
typedef o3dx_view o3dx_mview;
static const o3dx_view o3dx_view_null;

#if defined(_MSC_VER)
#define O3DX_TLS __declspec(thread)
#else
#define O3DX_TLS __thread
#endif
#define O3DX_DISPOSED (-1000) /* a disposed/closed object was used */
static O3DX_TLS o3d_status o3dx_err;    /* the status of the wrapped call, raised by %exception */
static O3DX_TLS char o3dx_msg[256];     /* a binding-side message, else o3d_last_error_message() */
#define O3DX_CHECK(call) do { if ((o3dx_err = (call)) != O3D_OK) goto fail; } while (0)

static void o3dx_fail(o3d_status status, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(o3dx_msg, sizeof o3dx_msg, fmt, ap);
  va_end(ap);
  o3dx_err = status;
}
static void o3dx_fail_len(const char *name, size_t width) {
  o3dx_fail(O3D_ERROR_INVALID_ARGUMENT, "`%s` needs a length that is %zu or a multiple of it", name, width);
}
static void o3dx_fail_taken(const char *name) {
  o3dx_fail(O3D_ERROR_INVALID_ARGUMENT, "`%s` was already taken from this result", name);
}
/* "O3D_ERROR_X: message", the message being the binding's own or o3d_last_error_message() */
static const char *o3dx_message(void) {
  static O3DX_TLS char text[1024];
  snprintf(text, sizeof text, "%s: %s", o3d_status_string(o3dx_err), o3dx_msg[0] ? o3dx_msg : o3d_last_error_message());
  return text;
}

#define O3DX_ALLOC(e, T) \
  static o3dx_out_##e o3dx_alloc_##e(size_t n) { \
    o3dx_out_##e r; r.p = (T *)malloc(n ? n * sizeof(T) : 1); r.n = n; r.owned = 1; \
    if (!r.p) o3dx_fail(O3D_ERROR_OUT_OF_MEMORY, "out of memory"); \
    return r; }
O3DX_ALLOC(f64, double)
O3DX_ALLOC(f32, float)
O3DX_ALLOC(i32, int32_t)
O3DX_ALLOC(i64, int64_t)
O3DX_ALLOC(u8, uint8_t)

/* Counts that size copy-outs (cheap getters without side effects). */
typedef o3d_status (*o3dx_count_fn)(size_t *, const void *);
static size_t o3dx_count_(o3dx_count_fn fn, const void *h) { size_t n = 0; fn(&n, h); return n; }
#define o3dx_count(fn, h) o3dx_count_((o3dx_count_fn)(fn), (h))
typedef o3d_status (*o3dx_shape_fn)(size_t *, size_t *, const void *, int32_t);
static size_t o3dx_cols_(o3dx_shape_fn fn, const void *h, int32_t which) {
  size_t rows = 0, cols = 0;
  return fn(&rows, &cols, h, which) == O3D_OK && cols ? cols : 1;
}
#define o3dx_cols(fn, h, which) o3dx_cols_((o3dx_shape_fn)(fn), (h), (which))
/* UTF-8 text results (TEXT in gen_swig_interface.py): copied out of the buffer, which is destroyed;
   each language makes its string from the copy and frees it. */
typedef char *o3dx_text;
static o3dx_text o3dx_text_of(o3d_buffer_t *b) {
  const uint8_t *p = NULL;
  size_t n = 0;
  char *s = b && o3d_buffer_view(&p, &n, b) == O3D_OK ? (char *)malloc(n + 1) : NULL;
  if (s) { memcpy(s, p, n); s[n] = 0; } else if (b) o3dx_fail(O3D_ERROR_OUT_OF_MEMORY, "out of memory");
  o3d_buffer_destroy(b);
  return s;
}
/* The Visualizer's callbacks by kind (0: animation, 1: key, 2: key action); `fn` is the language's
   trampoline of that kind's type, NULL to remove. */
static o3d_status o3dx_visualizer_register(o3d_visualizer_t *v, int32_t kind, int32_t key, void (*fn)(void), void *user_data) {
  if (kind == 0) return o3d_visualizer_register_animation_callback(v, (o3d_visualizer_animation_callback)fn, user_data);
  return (kind == 1 ? o3d_visualizer_register_key_callback : o3d_visualizer_register_key_action_callback)(
      v, key, (o3d_visualizer_key_callback)fn, user_data);
}
static size_t o3dx_search_count(const o3d_search_result_t *r, int total) {
  size_t nq = 0, n = 0;
  o3d_search_result_counts(&nq, &n, r);
  return total ? n : nq + 1;
}
%}

%include <stdint.i>
/* o3d counts and seeds are 64-bit in both languages (long); SWIG runs with -DSWIGWORDSIZE64. */
%apply long long { size_t, uint64_t, int64_t };
typedef int32_t o3d_status;

/* ---- errors: one place for every call ----------------------------------------------------- */
%exception {
  o3dx_err = O3D_OK;
  o3dx_msg[0] = 0;
  $action
  if (o3dx_err != O3D_OK) {
    O3D_SWIG_RAISE(o3dx_err, o3dx_message());
    return $null;
  }
}
/* a disposed (C#) or closed (Java) object has a NULL pointer */
%typemap(check) SWIGTYPE *self %{
  if (!$1) {
    O3D_SWIG_RAISE(O3DX_DISPOSED, "the object was disposed");
    return $null;
  }
%}

/* ---- names: PascalCase (C#) / lowerCamelCase (Java) ---------------------------------------- */
#if defined(SWIGCSHARP)
%rename("%(camelcase)s", %$isfunction) "";
%rename("%(camelcase)s", %$isvariable, %$ismember) "";
%include "../csharp/o3d_csharp.i"
#elif defined(SWIGJAVA)
%rename("%(lowercamelcase)s", %$isfunction) "";
%rename("%(lowercamelcase)s", %$isvariable, %$ismember) "";
%include "../java/o3d_java.i"
#else
#error "o3d.i: only C# and Java are supported"
#endif

%include "o3d_generated.i"
