/* talkface: the C ABI (C99). Link with -ltalkface_c (pkg-config talkface_c).
 *
 *   tf_face_model *face = NULL;
 *   if (tf_face_model_load("face.xml", &face) != TF_OK) {
 *       fprintf(stderr, "%s\n", tf_last_error_message());
 *       return 1;
 *   }
 *   ...
 *   tf_face_model_destroy(face);
 *
 * Conventions:
 * - Every name is prefixed tf_ / TF_. Handles are opaque; each tf_X_create / tf_X_load has a
 *   tf_X_destroy, which accepts NULL.
 * - Fallible calls return tf_status (TF_OK = 0) and give results through out-parameters, which are
 *   left unchanged on failure. No C++ exception ever crosses this boundary.
 * - On failure, tf_last_error_message() holds the full message (file, line, point, time) for the
 *   calling thread until that thread's next tf_ call.
 * - Documents we build (SVG, XML, JSON) come back as (char **out, size_t *out_len), NUL-terminated,
 *   to be released with tf_free() (not free(): the allocator may differ).
 * - Borrowed pointers (const char * getters) stay valid while their handle lives unmodified.
 * - Angles are degrees, times seconds, coordinates image pixels with y down.
 * - Thread safety: distinct handles may be used from distinct threads; a handle is not locked.
 */
#ifndef TALKFACE_TALKFACE_H
#define TALKFACE_TALKFACE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__GNUC__)
#define TF_API __attribute__((visibility("default")))
#else
#define TF_API
#endif

/* Status codes: equal to talkface::ErrorCode, never renumbered within a major version. */
typedef enum tf_status {
    TF_OK = 0,
    TF_ERR_INVALID_ARGUMENT = 1, /* a value passed is out of range, malformed or NULL */
    TF_ERR_FILE = 2,             /* a file could not be opened, read, written or renamed */
    TF_ERR_PARSE = 3,            /* a file's content is wrong (the message names file:line:column) */
    TF_ERR_ALIGNMENT = 4,        /* audio and transcript cannot be matched */
    TF_ERR_CANCELLED = 5,        /* a progress callback asked to stop */
    TF_ERR_OUT_OF_MEMORY = 6,    /* an allocation failed */
    TF_ERR_INTERNAL = 7          /* a bug in talkface */
} tf_status;

/* "TF_OK", "TF_ERR_PARSE", ...; "TF_ERR_UNKNOWN" for a value outside the enum. Never NULL. */
TF_API const char *tf_status_name(tf_status status);

/* The message of this thread's last failed tf_ call; "" if there was none. Never NULL. */
TF_API const char *tf_last_error_message(void);

/* The loaded library's version, "MAJOR.MINOR.PATCH". */
TF_API const char *tf_version(void);

/* Releases a document returned by talkface (SVG, XML, JSON). Accepts NULL. */
TF_API void tf_free(void *document);

#ifdef __cplusplus
}
#endif

#endif
