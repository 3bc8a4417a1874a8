/* talkface: the C calls of talkface::photo, a face model from a photo (C99).
 *
 * The photo stage is its own library, so that programs that never read a photo load none of OpenCV,
 * libpng, libjpeg or dlib: link libtalkface_photo (`pkg-config talkface_photo`, or talkface::photo
 * in CMake) besides libtalkface_c. Status codes, tf_last_error_message() and tf_face_model are those
 * of talkface/talkface.h.
 */
#ifndef TALKFACE_TALKFACE_PHOTO_H
#define TALKFACE_TALKFACE_PHOTO_H

#include <stddef.h>
#include <stdint.h>

#include "talkface/talkface.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------------------------------
 * Face from a photo (SPEC step 1; thesis 2.2, Chen and Tsai's method; talkface/face_from_photo.hpp).
 * The points are in the photo's pixels. Photo errors are TF_ERR_INVALID_ARGUMENT with a message that
 * names the photo and what was wrong: no face, several faces (set a face index), face too small, too
 * dark, not frontal enough. A missing Haar cascade or dlib model is TF_ERR_FILE.
 * ------------------------------------------------------------------------------------------- */

/* How the bytes of one pixel are laid out (8 bits per channel). */
typedef enum tf_pixel_format {
    TF_PIXEL_FORMAT_GRAY8 = 0,
    TF_PIXEL_FORMAT_RGB8 = 1,
    TF_PIXEL_FORMAT_BGR8 = 2,
    TF_PIXEL_FORMAT_RGBA8 = 3
} tf_pixel_format;

/* Which locator finds eyes, brows, nose, mouth and jaw. */
typedef enum tf_photo_locator {
    TF_PHOTO_LOCATOR_THESIS = 0,    /* knowledge-based edge detection, OpenCV only */
    TF_PHOTO_LOCATOR_DLIB = 1,      /* dlib's 68-point shape predictor */
    TF_PHOTO_LOCATOR_AUTOMATIC = 2  /* dlib where built in and installed, else thesis */
} tf_photo_locator;

/* 1 if this build has the dlib locator, else 0. */
TF_API int tf_has_dlib_locator(void);

/* Options for reading a photo; NULL everywhere means the defaults (automatic locator, refuse a
 * photo with several faces, opencv-data's cascades, libdlib-data's model). Created by
 * tf_photo_options_create, released by tf_photo_options_destroy. */
typedef struct tf_photo_options tf_photo_options;

/* Errors: TF_ERR_INVALID_ARGUMENT if out is NULL. */
TF_API tf_status tf_photo_options_create(tf_photo_options **out);
/* Releases options. Accepts NULL. */
TF_API void tf_photo_options_destroy(tf_photo_options *options);
/* Errors: TF_ERR_INVALID_ARGUMENT for a value outside tf_photo_locator or a NULL options. */
TF_API tf_status tf_photo_options_set_locator(tf_photo_options *options, tf_photo_locator locator);
/* Which face to use when the photo shows several, 0 = leftmost; -1 refuses such a photo.
 * Errors: TF_ERR_INVALID_ARGUMENT if face_index < -1 or options is NULL. */
TF_API tf_status tf_photo_options_set_face_index(tf_photo_options *options, int face_index);
/* Folder holding OpenCV's Haar cascades (copied). Errors: TF_ERR_INVALID_ARGUMENT for NULL. */
TF_API tf_status tf_photo_options_set_cascade_dir(tf_photo_options *options, const char *folder);
/* dlib's shape_predictor_68_face_landmarks.dat (copied). Errors: TF_ERR_INVALID_ARGUMENT for NULL. */
TF_API tf_status tf_photo_options_set_dlib_model_path(tf_photo_options *options, const char *path);
/* The smallest face accepted, as its detected width in pixels (64 by default; at least 16, which the
 * photo's reading checks, naming min_face_width_px): a smaller face is refused naming its width.
 * Errors: TF_ERR_INVALID_ARGUMENT for a NULL options. */
TF_API tf_status tf_photo_options_set_min_face_width_px(tf_photo_options *options, int min_face_width_px);

/* What a photo gave: the face and the confidence of every located feature. Created by
 * tf_photo_result_from_file / _from_pixels, released by tf_photo_result_destroy. */
typedef struct tf_photo_result tf_photo_result;

/* Reads a PNG or JPEG photo (at most 100 megapixels) and extracts its face. options may be NULL.
 * Errors: TF_ERR_FILE if the photo cannot be read or decoded (the message names the path and why:
 * missing, another format, broken, truncated, too large); TF_ERR_INVALID_ARGUMENT as described above. */
TF_API tf_status tf_photo_result_from_file(const char *path, const tf_photo_options *options,
                                           tf_photo_result **out);
/* The same from pixels the caller owns (row y at pixels + y * stride_bytes), read during the call.
 * Errors: TF_ERR_INVALID_ARGUMENT for a malformed image or as described above. */
TF_API tf_status tf_photo_result_from_pixels(const uint8_t *pixels, int width, int height, int stride_bytes,
                                             tf_pixel_format format, const tf_photo_options *options,
                                             tf_photo_result **out);
/* Releases a result. Accepts NULL. */
TF_API void tf_photo_result_destroy(tf_photo_result *result);
/* A copy of the extracted face; release it with tf_face_model_destroy.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_photo_result_face(const tf_photo_result *result, tf_face_model **out);
/* The number of located features. Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_photo_result_feature_count(const tf_photo_result *result, size_t *out_count);
/* Feature `index`: its name (borrowed, valid while the result lives), confidence 0..1, and whether
 * its points come from the default face's proportions because it was not found (1) or not (0).
 * Any out pointer may be NULL. Errors: TF_ERR_INVALID_ARGUMENT if index is out of range. */
TF_API tf_status tf_photo_result_feature(const tf_photo_result *result, size_t index, const char **out_name,
                                         double *out_confidence, int *out_from_prior);
/* The confidence of the named feature ("left_eye", "mouth", "hair", ...).
 * Errors: TF_ERR_INVALID_ARGUMENT for an unknown name or a NULL argument. */
TF_API tf_status tf_photo_result_confidence(const tf_photo_result *result, const char *feature_name,
                                            double *out_confidence);
/* The locator that was used (never TF_PHOTO_LOCATOR_AUTOMATIC).
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_photo_result_locator(const tf_photo_result *result, tf_photo_locator *out_locator);
/* Writes the photo at photo_path with the extracted points drawn on it as a PNG, atomically.
 * Errors: TF_ERR_FILE if the photo cannot be read or the PNG written. */
TF_API tf_status tf_photo_result_write_overlay(const tf_photo_result *result, const char *photo_path,
                                               const char *output_png_path);

/* Shortcuts that keep only the face. options may be NULL. Errors as tf_photo_result_from_*. */
TF_API tf_status tf_face_model_from_photo_file(const char *path, const tf_photo_options *options,
                                               tf_face_model **out);
TF_API tf_status tf_face_model_from_photo_pixels(const uint8_t *pixels, int width, int height, int stride_bytes,
                                                 tf_pixel_format format, const tf_photo_options *options,
                                                 tf_face_model **out);

#ifdef __cplusplus
}
#endif

#endif
