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
 * - Thread safety: handles are not locked. Read-only calls (const handle parameters) may share a
 *   handle across threads; a handle being modified must not be used by another thread meanwhile.
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

/* ---------------------------------------------------------------------------------------------
 * Colours
 * ------------------------------------------------------------------------------------------- */

/* An sRGB colour, 0..255 per channel. */
typedef struct tf_rgb {
    uint8_t r;
    uint8_t g;
    uint8_t b;
} tf_rgb;

/* Parses "#rrggbb" or "#rgb" (either case) into *out.
 * Errors: TF_ERR_INVALID_ARGUMENT if text or out is NULL or text is not such a colour. */
TF_API tf_status tf_rgb_from_hex(const char *text, tf_rgb *out);

/* Writes "#rrggbb" (lower case, NUL-terminated, 8 bytes with the NUL) into out_hex.
 * Errors: TF_ERR_INVALID_ARGUMENT if out_hex is NULL. */
TF_API tf_status tf_rgb_to_hex(tf_rgb colour, char out_hex[8]);

/* ---------------------------------------------------------------------------------------------
 * Face model (SPEC step 1): 72 named feature points in image pixels (y down) and 12 FAPUs.
 * ------------------------------------------------------------------------------------------- */

/* A face model. Created by tf_face_model_default / _load / _from_xml / _clone, tf_place_face,
 * tf_apply_expression, tf_apply_mouth, tf_projected_face_face; released by tf_face_model_destroy. */
typedef struct tf_face_model tf_face_model;

/* The number of feature points, 72. */
TF_API size_t tf_face_point_count(void);
/* The id of point `index` (0 .. tf_face_point_count() - 1) in file order: "hair.1" .. "hair.23",
 * "11.1", ..., "EyeballRight". A static string (never freed); NULL if index is out of range. */
TF_API const char *tf_face_point_id(size_t index);
/* The number of FAPUs, 12. */
TF_API size_t tf_face_fapu_count(void);
/* The name of FAPU `index` (0 .. tf_face_fapu_count() - 1) in file order: "d", "EyebrowH", ...,
 * "r2". A static string (never freed); NULL if index is out of range. */
TF_API const char *tf_face_fapu_name(size_t index);

/* The built-in default face, compiled into the library.
 * Errors: TF_ERR_INVALID_ARGUMENT if out is NULL. */
TF_API tf_status tf_face_model_default(tf_face_model **out);

/* Reads a face file (docs/face-format.md) into a new face *out.
 * Errors: TF_ERR_FILE if it cannot be read (the message names the path);
 *         TF_ERR_PARSE if its content is wrong (the message names path:line:column and the point);
 *         TF_ERR_INVALID_ARGUMENT if path or out is NULL. */
TF_API tf_status tf_face_model_load(const char *path, tf_face_model **out);

/* Parses the `length` bytes at `text` (a face file's content; need not be NUL-terminated) into a new
 * face *out. `source_name` stands for the path in error messages; NULL means "<string>".
 * Errors: TF_ERR_PARSE as tf_face_model_load; TF_ERR_INVALID_ARGUMENT if text or out is NULL. */
TF_API tf_status tf_face_model_from_xml(const char *text, size_t length, const char *source_name,
                                        tf_face_model **out);

/* Writes the face file atomically (a temporary file renamed over `path`): on failure `path` is
 * untouched. tf_face_model_load(path) gives back an equal face, bit for bit.
 * Errors: TF_ERR_FILE if it cannot be written; TF_ERR_INVALID_ARGUMENT if face or path is NULL. */
TF_API tf_status tf_face_model_save(const tf_face_model *face, const char *path);

/* The face file's text (what tf_face_model_save writes) as a new document: release *out_xml with
 * tf_free. *out_len (if out_len is not NULL) is its length in bytes without the NUL.
 * Errors: TF_ERR_INVALID_ARGUMENT if face or out_xml is NULL. */
TF_API tf_status tf_face_model_to_xml(const tf_face_model *face, char **out_xml, size_t *out_len);

/* A new, independent copy of `face`.
 * Errors: TF_ERR_INVALID_ARGUMENT if face or out is NULL. */
TF_API tf_status tf_face_model_clone(const tf_face_model *face, tf_face_model **out);

/* Releases a face. Accepts NULL. */
TF_API void tf_face_model_destroy(tf_face_model *face);

/* *out_equal = 1 if the two faces have equal points, FAPUs, colours and names, else 0.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_face_model_equal(const tf_face_model *a, const tf_face_model *b, int *out_equal);

/* A point's image position, pixels (y down).
 * Errors: TF_ERR_INVALID_ARGUMENT for an unknown id (the message names it) or a NULL argument. */
TF_API tf_status tf_face_model_point(const tf_face_model *face, const char *id, double *out_x,
                                     double *out_y);

/* Moves a point to (x, y), image pixels.
 * Errors: TF_ERR_INVALID_ARGUMENT for an unknown id, a non-finite coordinate or a NULL argument. */
TF_API tf_status tf_face_model_set_point(tf_face_model *face, const char *id, double x, double y);

/* A FAPU's value, pixels ("d", "MW0", ...).
 * Errors: TF_ERR_INVALID_ARGUMENT for an unknown name or a NULL argument. */
TF_API tf_status tf_face_model_fapu(const tf_face_model *face, const char *name, double *out_value_px);

/* Sets a FAPU, pixels.
 * Errors: TF_ERR_INVALID_ARGUMENT for an unknown name, a value that is not finite and positive, or a
 * NULL argument. */
TF_API tf_status tf_face_model_set_fapu(tf_face_model *face, const char *name, double value_px);

/* The face's label (e.g. "default") in *out_name, borrowed: valid until the face is modified or
 * destroyed. Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_face_model_name(const tf_face_model *face, const char **out_name);

/* Sets the face's label (copied). Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_face_model_set_name(tf_face_model *face, const char *name);

/* The colours a face is drawn with (part of the face file). */
typedef enum tf_face_color {
    TF_FACE_COLOR_SKIN = 0,
    TF_FACE_COLOR_HAIR = 1,
    TF_FACE_COLOR_BROWS = 2,
    TF_FACE_COLOR_EYE_WHITE = 3,
    TF_FACE_COLOR_IRIS = 4,
    TF_FACE_COLOR_LIPS = 5,
    TF_FACE_COLOR_MOUTH_INSIDE = 6,
    TF_FACE_COLOR_OUTLINE = 7
} tf_face_color;

/* One of the face's colours.
 * Errors: TF_ERR_INVALID_ARGUMENT for a value outside tf_face_color or a NULL argument. */
TF_API tf_status tf_face_model_color(const tf_face_model *face, tf_face_color which, tf_rgb *out);

/* Sets one of the face's colours.
 * Errors: TF_ERR_INVALID_ARGUMENT for a value outside tf_face_color or a NULL face. */
TF_API tf_status tf_face_model_set_color(tf_face_model *face, tf_face_color which, tf_rgb colour);

/* ---------------------------------------------------------------------------------------------
 * 3D lift (SPEC step 2). Local frame: pixels, x towards the image left, y up, z towards the viewer,
 * origin at the rotation origin O (the neck).
 * ------------------------------------------------------------------------------------------- */

/* A face lifted into 3D: O, d, and the 72 model points followed by the 17 additional points A..S,
 * each with its local (x, y, z). Created by tf_lift_face, released by tf_lifted_face_destroy. */
typedef struct tf_lifted_face tf_lifted_face;

/* Lifts a face into 3D (thesis Algorithm 2.1, Table 2.1; S is placed at 8.3).
 * Errors: TF_ERR_INVALID_ARGUMENT if the face's d is not positive or an argument is NULL. */
TF_API tf_status tf_lift_face(const tf_face_model *face, tf_lifted_face **out);

/* Releases a lifted face. Accepts NULL. */
TF_API void tf_lifted_face_destroy(tf_lifted_face *lifted);

/* The rotation origin O in image pixels and the eyeball distance d in pixels.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_lifted_face_origin(const tf_lifted_face *lifted, double *out_x, double *out_y,
                                       double *out_d_px);

/* The number of points (72 + 17 = 89) in *out_count.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_lifted_face_point_count(const tf_lifted_face *lifted, size_t *out_count);

/* The id of point `index` in *out_id, borrowed: valid while `lifted` lives.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or an argument is NULL. */
TF_API tf_status tf_lifted_face_point_id(const tf_lifted_face *lifted, size_t index,
                                         const char **out_id);

/* A point's local position (x, y, z), pixels, by id ("3.2", "A", ...).
 * Errors: TF_ERR_INVALID_ARGUMENT for an unknown id or a NULL argument. */
TF_API tf_status tf_lifted_face_local(const tf_lifted_face *lifted, const char *id,
                                      double out_local_xyz[3]);

/* Table 2.1: a point's depth in units of d.
 * Errors: TF_ERR_INVALID_ARGUMENT for an unknown id or a NULL argument. */
TF_API tf_status tf_depth_in_d(const char *id, double *out_depth_in_d);

/* The rotation origin O of Algorithm 2.1 step 3, image pixels.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_rotation_origin(const tf_face_model *face, double *out_x, double *out_y);

/* Image to local: x' = x_o - x, y' = y_o - y, z kept; the exact inverse of tf_to_image.
 * Errors: TF_ERR_INVALID_ARGUMENT if out_local_xyz is NULL. */
TF_API tf_status tf_to_local(double image_x, double image_y, double z, double origin_x, double origin_y,
                             double out_local_xyz[3]);

/* Local to image, orthographic: x = x_o - x', y = y_o - y' (z dropped).
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_to_image(const double local_xyz[3], double origin_x, double origin_y,
                             double *out_x, double *out_y);

/* A new face: `face` moved so its rotation origin is at (origin_x, origin_y) and scaled so its d is
 * d_px (every point and FAPU scales by d_px / d).
 * Errors: TF_ERR_INVALID_ARGUMENT if d_px is not finite and positive or an argument is NULL. */
TF_API tf_status tf_place_face(const tf_face_model *face, double origin_x, double origin_y, double d_px,
                               tf_face_model **out);

/* ---------------------------------------------------------------------------------------------
 * Rotation (SPEC step 3): R = Rz(gamma) Rx(alpha) Ry(beta), degrees. alpha > 0 nods down, beta > 0
 * turns towards the image left, gamma > 0 tilts the top of the head towards the image right.
 * ------------------------------------------------------------------------------------------- */

/* The 3x3 rotation matrix, row-major, into out_matrix[9]. Orthonormal with determinant 1.
 * Errors: TF_ERR_INVALID_ARGUMENT naming the angle if one is not finite, or out_matrix is NULL. */
TF_API tf_status tf_rotation3d_matrix(double alpha_deg, double beta_deg, double gamma_deg,
                                      double out_matrix[9]);

/* out_xyz = R in_xyz (local frame). in_xyz and out_xyz may be the same array.
 * Errors: TF_ERR_INVALID_ARGUMENT naming the angle if one is not finite, or an array is NULL. */
TF_API tf_status tf_rotation3d_rotate(double alpha_deg, double beta_deg, double gamma_deg,
                                      const double in_xyz[3], double out_xyz[3]);

/* out_xyz = R^T in_xyz, the inverse rotation. Errors as tf_rotation3d_rotate. */
TF_API tf_status tf_rotation3d_unrotate(double alpha_deg, double beta_deg, double gamma_deg,
                                        const double in_xyz[3], double out_xyz[3]);

/* ---------------------------------------------------------------------------------------------
 * Expressions and mouth shapes (thesis 2.4.2, 5.2.2). Mouth control points: up = 8.9, down = 8.2,
 * left = 8.4, right = 8.3, each an (x, y) pair in image pixels.
 * ------------------------------------------------------------------------------------------- */

/* The 12 basic mouth shapes; values equal talkface::MouthShape, stable within a major version. */
typedef enum tf_mouth_shape {
    TF_MOUTH_M = 0,
    TF_MOUTH_F = 1,
    TF_MOUTH_H_PRIME = 2,
    TF_MOUTH_H = 3,
    TF_MOUTH_R = 4,
    TF_MOUTH_Z = 5,
    TF_MOUTH_A = 6,
    TF_MOUTH_I = 7,
    TF_MOUTH_U = 8,
    TF_MOUTH_E = 9,
    TF_MOUTH_O = 10,
    TF_MOUTH_N = 11
} tf_mouth_shape;

/* The number of mouth shapes; valid values are 0 .. TF_MOUTH_SHAPE_COUNT - 1. */
#define TF_MOUTH_SHAPE_COUNT 12

/* The thesis's name of a shape: "m", "f", "h'", "h", "r", "z", "a", "i", "u", "e", "o", "n".
 * A static string; NULL for a value outside tf_mouth_shape. */
TF_API const char *tf_mouth_shape_name(tf_mouth_shape shape);

/* Parses a name as tf_mouth_shape_name writes it ("h_prime" is accepted for "h'").
 * Errors: TF_ERR_INVALID_ARGUMENT listing the valid names, or for a NULL argument. */
TF_API tf_status tf_mouth_shape_from_name(const char *name, tf_mouth_shape *out);

/* The mouth control points of the neutral face (shape m is this), image pixels.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_neutral_mouth_controls(const tf_face_model *neutral, double out_up[2],
                                           double out_down[2], double out_left[2], double out_right[2]);

/* A shape's control points: thesis 5.2.2's formulas in FAPU multiples of the neutral face.
 * Errors: TF_ERR_INVALID_ARGUMENT for a value outside tf_mouth_shape or a NULL argument. */
TF_API tf_status tf_mouth_controls(const tf_face_model *neutral, tf_mouth_shape shape, double out_up[2],
                                   double out_down[2], double out_left[2], double out_right[2]);

/* A new face: `neutral` with its mouth set to the control points (8.1, 8.10, the inner lips and the
 * jaw follow them). Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_apply_mouth(const tf_face_model *neutral, const double up[2], const double down[2],
                                const double left[2], const double right[2], tf_face_model **out);

/* A new face: `face` with an expression applied; amounts 0..1 (blink 1 = closed eye).
 * Errors: TF_ERR_INVALID_ARGUMENT naming the amount if one is outside 0..1 or not finite, or for a
 * NULL argument. */
TF_API tf_status tf_apply_expression(const tf_face_model *face, double blink_left, double blink_right,
                                     double smile, double brows, tf_face_model **out);

/* ---------------------------------------------------------------------------------------------
 * Face state and projection (SPEC step 3): what changes from frame to frame.
 * ------------------------------------------------------------------------------------------- */

/* Pose, expression and mouth of one frame. Created by tf_face_state_create (frontal, neutral,
 * neutral mouth), released by tf_face_state_destroy. The setters check their values at once. */
typedef struct tf_face_state tf_face_state;

/* The largest head rotation about any axis, degrees (thesis 1.3.2). */
#define TF_MAX_POSE_ANGLE_DEG 15.0

/* A new state: frontal pose, no expression, neutral mouth.
 * Errors: TF_ERR_INVALID_ARGUMENT if out is NULL. */
TF_API tf_status tf_face_state_create(tf_face_state **out);

/* Releases a state. Accepts NULL. */
TF_API void tf_face_state_destroy(tf_face_state *state);

/* Sets the head pose, degrees (see Rotation above).
 * Errors: TF_ERR_INVALID_ARGUMENT naming the angle (alpha_deg, beta_deg, gamma_deg) if it is outside
 * +-TF_MAX_POSE_ANGLE_DEG or not finite, or if state is NULL; the state is then unchanged. */
TF_API tf_status tf_face_state_set_pose(tf_face_state *state, double alpha_deg, double beta_deg,
                                        double gamma_deg);

/* Sets the blink amounts of the image-left and image-right eye, 0..1 (1 = closed).
 * Errors: TF_ERR_INVALID_ARGUMENT naming the amount if outside 0..1 or not finite, or NULL state. */
TF_API tf_status tf_face_state_set_blink(tf_face_state *state, double left, double right);

/* Sets the smile amount, 0..1 (mouth corners up by UpperLipH, lower lids up).
 * Errors: TF_ERR_INVALID_ARGUMENT if outside 0..1 or not finite, or NULL state. */
TF_API tf_status tf_face_state_set_smile(tf_face_state *state, double amount);

/* Sets the eyebrow raise, 0..1 (eyebrows up by EyebrowH).
 * Errors: TF_ERR_INVALID_ARGUMENT if outside 0..1 or not finite, or NULL state. */
TF_API tf_status tf_face_state_set_brows(tf_face_state *state, double amount);

/* Sets the mouth to `shape` as computed for the neutral face `face` (tf_mouth_controls).
 * Errors: TF_ERR_INVALID_ARGUMENT for a value outside tf_mouth_shape or a NULL argument. */
TF_API tf_status tf_face_state_set_mouth_shape(tf_face_state *state, const tf_face_model *face,
                                               tf_mouth_shape shape);

/* Sets the mouth control points directly, image pixels (key-frame interpolation gives these).
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL or a coordinate is not finite. */
TF_API tf_status tf_face_state_set_mouth_controls(tf_face_state *state, const double up[2],
                                                  const double down[2], const double left[2],
                                                  const double right[2]);

/* Sets the neutral mouth (the face's own mouth points).
 * Errors: TF_ERR_INVALID_ARGUMENT if state is NULL. */
TF_API tf_status tf_face_state_set_neutral_mouth(tf_face_state *state);

/* A face projected at a state: every point in image pixels. Created by tf_project_face, released by
 * tf_projected_face_destroy. */
typedef struct tf_projected_face tf_projected_face;

/* Which side of the nose the bridge line is drawn from (Algorithm 2.3 step 8). */
typedef enum tf_side { TF_SIDE_LEFT = 0, TF_SIDE_RIGHT = 1 } tf_side;

/* Projects `face` (a neutral face) at `state` (thesis Algorithm 2.3): expression and mouth applied,
 * lifted, hair depth shifted, rotated, gaze held, projected, contour substituted past 10 degrees.
 * Errors: TF_ERR_INVALID_ARGUMENT if the state does not fit the face or an argument is NULL. */
TF_API tf_status tf_project_face(const tf_face_model *face, const tf_face_state *state,
                                 tf_projected_face **out);

/* Releases a projected face. Accepts NULL. */
TF_API void tf_projected_face_destroy(tf_projected_face *projected);

/* A point's image position (pixels) by id: the 72 model ids and "A" .. "S"; eyeball ids hold the
 * pupils after gaze. Errors: TF_ERR_INVALID_ARGUMENT for an unknown id or a NULL argument. */
TF_API tf_status tf_projected_face_point(const tf_projected_face *projected, const char *id,
                                         double *out_x, double *out_y);

/* The number of points (89) in *out_count. Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_projected_face_point_count(const tf_projected_face *projected, size_t *out_count);

/* The id of point `index` in *out_id, borrowed: valid while `projected` lives.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or an argument is NULL. */
TF_API tf_status tf_projected_face_point_id(const tf_projected_face *projected, size_t index,
                                            const char **out_id);

/* The face contour's point ids on one side: out_ids[0..2] = forehead, cheek, jaw (after the contour
 * substitution past 10 degrees), borrowed: valid while `projected` lives.
 * Errors: TF_ERR_INVALID_ARGUMENT for a value outside tf_side or a NULL argument. */
TF_API tf_status tf_projected_face_contour(const tf_projected_face *projected, tf_side side,
                                           const char *out_ids[3]);

/* The side of the nose the bridge line is drawn from.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_projected_face_nose_bridge(const tf_projected_face *projected, tf_side *out_side);

/* The rotation origin O (image pixels) and d (pixels) of the projection.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_projected_face_origin(const tf_projected_face *projected, double *out_x,
                                          double *out_y, double *out_d_px);

/* A new face: the 2D face with expression and mouth applied, before the pose.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_projected_face_face(const tf_projected_face *projected, tf_face_model **out);

/* ---------------------------------------------------------------------------------------------
 * Rendering (SPEC step 7): SVG 1.1 in layers background, hair, clothes, face.
 * ------------------------------------------------------------------------------------------- */

/* How a face is drawn. Created by tf_svg_options_create with the defaults (a light blue-grey
 * background, clothes drawn, outline 0.025 d, 2 decimals, canvas fitted to the face); released by
 * tf_svg_options_destroy. Values are checked when rendering. */
typedef struct tf_svg_options tf_svg_options;

/* New options with the defaults. Errors: TF_ERR_INVALID_ARGUMENT if out is NULL. */
TF_API tf_status tf_svg_options_create(tf_svg_options **out);

/* Releases options. Accepts NULL. */
TF_API void tf_svg_options_destroy(tf_svg_options *options);

/* Sets the background colour; NULL leaves the background transparent (no background layer).
 * Errors: TF_ERR_INVALID_ARGUMENT if options is NULL. */
TF_API tf_status tf_svg_options_set_background(tf_svg_options *options, const tf_rgb *colour);

/* Draws the clothes layer (neck and shoulders) if draw_clothes is non-zero, in `colour`.
 * Errors: TF_ERR_INVALID_ARGUMENT if options is NULL. */
TF_API tf_status tf_svg_options_set_clothes(tf_svg_options *options, int draw_clothes, tf_rgb colour);

/* Sets the outline width, in units of d.
 * Errors: TF_ERR_INVALID_ARGUMENT if options is NULL (the value is checked when rendering). */
TF_API tf_status tf_svg_options_set_stroke_width_in_d(tf_svg_options *options, double stroke_width_in_d);

/* Sets the digits after the point in coordinates (0..6).
 * Errors: TF_ERR_INVALID_ARGUMENT if options is NULL (the value is checked when rendering). */
TF_API tf_status tf_svg_options_set_decimals(tf_svg_options *options, int decimals);

/* Sets the canvas size, pixels; 0 and 0 fit the face at any pose with a margin.
 * Errors: TF_ERR_INVALID_ARGUMENT if options is NULL (the values are checked when rendering). */
TF_API tf_status tf_svg_options_set_size_px(tf_svg_options *options, int width_px, int height_px);

/* Renders `face` (a neutral face) at `state` as a standalone SVG document: release *out_svg with
 * tf_free; *out_len (if out_len is not NULL) is its length in bytes without the NUL.
 * `options` NULL means the defaults.
 * Errors: TF_ERR_INVALID_ARGUMENT if an option is out of range, the state does not fit the face, or
 * face, state or out_svg is NULL. */
TF_API tf_status tf_render_svg(const tf_face_model *face, const tf_face_state *state,
                               const tf_svg_options *options, char **out_svg, size_t *out_len);

/* Writes the SVG of tf_render_svg to `path` through a temporary file and a rename: a failure leaves
 * no partial file. `options` NULL means the defaults.
 * Errors: TF_ERR_FILE if it cannot be written (the message names the path); otherwise as
 * tf_render_svg. */
TF_API tf_status tf_write_svg(const tf_face_model *face, const tf_face_state *state,
                              const tf_svg_options *options, const char *path);

#ifdef __cplusplus
}
#endif

#endif
