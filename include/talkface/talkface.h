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

/* How a face's shapes are painted (talkface::FaceLook). */
typedef enum tf_face_look {
    TF_FACE_LOOK_OUTLINED = 0, /* the thesis's cartoon: filled shapes with dark outlines. The default. */
    TF_FACE_LOOK_FLAT = 1      /* no outlines: flat fills told apart by colour, soft shades */
} tf_face_look;

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

/* Sets how the shapes are painted. Errors: TF_ERR_INVALID_ARGUMENT if options is NULL (the value
 * is checked when rendering). */
TF_API tf_status tf_svg_options_set_look(tf_svg_options *options, tf_face_look look);

/* Sets the outline width, in units of d.
 * Errors: TF_ERR_INVALID_ARGUMENT if options is NULL (the value is checked when rendering). */
TF_API tf_status tf_svg_options_set_stroke_width_in_d(tf_svg_options *options, double stroke_width_in_d);

/* The most digits after the point tf_svg_options_set_decimals may ask for. */
#define TF_MAX_SVG_DECIMALS 6

/* Sets the digits after the point in coordinates (0..TF_MAX_SVG_DECIMALS).
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

/* Frames as pixels (talkface::FrameRenderer): the same layers as the SVG, drawn with cairo,
 * antialiased, into a caller's buffer of RGBA bytes (R, G, B, A in memory order, rows top to
 * bottom, stride_bytes apart). */

/* Where the face stands in a frame; values equal talkface::FrameLayout. */
typedef enum tf_frame_layout {
    /* Thesis 7.2: the frame is a stage, the face stands where the announcer page stands it: on its
     * bottom edge, centred, its canvas as tall as the frame, larger if its mouth would meet the
     * page's caption band (or placed by tf_frame_options_set_face_placement). The default. */
    TF_FRAME_LAYOUT_ANNOUNCER = 0,
    /* The face's SVG canvas fitted into the frame and centred, as a viewer shows tf_render_svg's
     * document at the frame's size. */
    TF_FRAME_LAYOUT_FACE = 1
} tf_frame_layout;

/* How the bytes of a pixel carry alpha; values equal talkface::AlphaMode. */
typedef enum tf_alpha_mode {
    TF_ALPHA_STRAIGHT = 0,      /* R, G, B not multiplied by A (PNG, FFmpeg's rgba). The default. */
    TF_ALPHA_PREMULTIPLIED = 1  /* R, G, B multiplied by A / 255 */
} tf_alpha_mode;

/* How frames are drawn. Created by tf_frame_options_create with the defaults (1280x720, the
 * announcer layout, background #1d3b5c, clothes drawn, outline 0.025 d, straight alpha); released by
 * tf_frame_options_destroy. Values are checked by tf_frame_renderer_create. */
typedef struct tf_frame_options tf_frame_options;

/* New options with the defaults. Errors: TF_ERR_INVALID_ARGUMENT if out is NULL. */
TF_API tf_status tf_frame_options_create(tf_frame_options **out);

/* Releases options. Accepts NULL. */
TF_API void tf_frame_options_destroy(tf_frame_options *options);

/* Sets the frame size, pixels: width 1..7680, height 1..4320.
 * Errors: TF_ERR_INVALID_ARGUMENT if options is NULL. */
TF_API tf_status tf_frame_options_set_size_px(tf_frame_options *options, int width_px, int height_px);

/* Sets where the face stands. Errors: TF_ERR_INVALID_ARGUMENT if options is NULL. */
TF_API tf_status tf_frame_options_set_layout(tf_frame_options *options, tf_frame_layout layout);

/* Sets the background colour; NULL leaves the frame transparent where nothing is drawn.
 * Errors: TF_ERR_INVALID_ARGUMENT if options is NULL. */
TF_API tf_status tf_frame_options_set_background(tf_frame_options *options, const tf_rgb *colour);

/* Draws the clothes layer if draw_clothes is non-zero, in `colour`.
 * Errors: TF_ERR_INVALID_ARGUMENT if options is NULL. */
TF_API tf_status tf_frame_options_set_clothes(tf_frame_options *options, int draw_clothes, tf_rgb colour);

/* Sets how the shapes are painted. Errors: TF_ERR_INVALID_ARGUMENT if options is NULL (the value
 * is checked by tf_frame_renderer_create). */
TF_API tf_status tf_frame_options_set_look(tf_frame_options *options, tf_face_look look);

/* Sets the outline width, in units of d. Errors: TF_ERR_INVALID_ARGUMENT if options is NULL. */
TF_API tf_status tf_frame_options_set_stroke_width_in_d(tf_frame_options *options, double stroke_width_in_d);

/* announcer: where the face's rotation origin O stands (origin_px: x, y in frame pixels; NULL:
 * centred, standing on the bottom edge) and its eye distance d in frame pixels (0: the canvas as
 * tall as the frame). Errors: TF_ERR_INVALID_ARGUMENT if options is NULL. */
TF_API tf_status tf_frame_options_set_face_placement(tf_frame_options *options, const double origin_px[2],
                                                     double face_d_px);

/* Sets how alpha is carried. Errors: TF_ERR_INVALID_ARGUMENT if options is NULL. */
TF_API tf_status tf_frame_options_set_alpha(tf_frame_options *options, tf_alpha_mode alpha);

/* Draws frames of one face; keeps the layers that do not move and the last frame, so that each
 * frame draws only what moved. One thread at a time per renderer. Created by
 * tf_frame_renderer_create, released by tf_frame_renderer_destroy. */
typedef struct tf_frame_renderer tf_frame_renderer;

/* A renderer of `face` (a neutral face); `options` NULL means the defaults.
 * Errors: TF_ERR_INVALID_ARGUMENT if face or out is NULL or an option is out of range (named). */
TF_API tf_status tf_frame_renderer_create(const tf_face_model *face, const tf_frame_options *options,
                                          tf_frame_renderer **out);

/* Releases a renderer. Accepts NULL. */
TF_API void tf_frame_renderer_destroy(tf_frame_renderer *renderer);

/* The frame's size in pixels; a buffer needs height_px rows of at least 4 * width_px bytes.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_frame_renderer_size(const tf_frame_renderer *renderer, int *width_px, int *height_px);

/* Draws a picture over the background colour, covering the frame (scaled to fill it, centred, the
 * overflow cropped), under the face. `rgba`: height rows of width straight-alpha RGBA pixels,
 * stride_bytes apart; copied.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL, a size is 0 or the stride too small. */
TF_API tf_status tf_frame_renderer_set_background_image(tf_frame_renderer *renderer, const uint8_t *rgba,
                                                        int width, int height, size_t stride_bytes);

/* Draws the face at `state` into `rgba`: every pixel of the frame is written.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL, stride_bytes < 4 * width, or the state
 * does not fit the face. */
TF_API tf_status tf_frame_renderer_render_rgba(tf_frame_renderer *renderer, const tf_face_state *state,
                                               uint8_t *rgba, size_t stride_bytes);

/* ---------------------------------------------------------------------------------------------
 * Transcripts and timelines (SPEC step 4): sentences and syllables in transcript order, with their
 * times once aligned. The JSON form is the SPEC "Contracts" `align` document.
 * ------------------------------------------------------------------------------------------- */

/* Sentences, syllables and the reader's warnings. Created by tf_read_transcript, tf_load_transcript
 * (or their forms that take tf_transcript_options) or tf_timeline_create; released by
 * tf_timeline_destroy. Indices are 0-based. */
typedef struct tf_timeline tf_timeline;

/* Reads a transcript (UTF-8 Traditional or Simplified characters, or numbered pinyin; reading fixes
 * such as 行{hang2}) from the `length` bytes at `text` (need not be NUL-terminated) into a new
 * timeline *out, times all 0. Characters without a reading become warnings, not errors.
 * `source_name` names the text in messages; NULL means "<transcript>". Read with the defaults of
 * tf_transcript_options (pinyin read, stage directions left out); tf_read_transcript_with_options
 * takes others.
 * Errors: TF_ERR_PARSE naming source:line:column (invalid UTF-8, a bad reading fix);
 *         TF_ERR_INVALID_ARGUMENT if text or out is NULL. */
TF_API tf_status tf_read_transcript(const char *text, size_t length, const char *source_name,
                                    tf_timeline **out);

/* Reads a transcript file as tf_read_transcript does; messages name `path`. The file may be UTF-8,
 * UTF-16 or UTF-32 with a byte order mark, or SRT or WebVTT subtitles or a Praat TextGrid, whose
 * text is read (talkface::load_transcript in transcript.hpp has the rules). A bracket of sounds and
 * actions, （笑） [掌声], and a dialogue's speaker labels, 主持人：, are left out with a warning.
 * Errors: TF_ERR_FILE if it cannot be read; TF_ERR_PARSE as tf_read_transcript, for a malformed
 *         subtitle or TextGrid, and for bytes that are not UTF-8 (the message names the encodings
 *         that read them as Chinese: GB18030, Big5, UTF-16; load such a file with
 *         tf_load_transcript_with); TF_ERR_INVALID_ARGUMENT if path or out is NULL. */
TF_API tf_status tf_load_transcript(const char *path, tf_timeline **out);

/* tf_load_transcript of a file in `encoding` when it has no byte order mark: any name iconv
 * knows, "gb18030" (GBK, GB2312), "big5", "big5-hkscs", "utf-16le", ...; NULL or "" means UTF-8.
 * keep_directions non-zero reads stage directions and speaker labels as text.
 * (tf_load_transcript_with_options takes these and the other options of a tf_transcript_options.)
 * Errors: as tf_load_transcript; TF_ERR_INVALID_ARGUMENT naming "encoding" for a name iconv does
 *         not know; TF_ERR_PARSE naming the line, column and byte offset where the bytes stop
 *         being text in `encoding`. */
TF_API tf_status tf_load_transcript_with(const char *path, const char *encoding, int keep_directions,
                                         tf_timeline **out);

/* How a transcript is read (talkface::TranscriptOptions). Created by tf_transcript_options_create
 * with the defaults (pinyin read as syllables, stage directions and speaker labels left out, UTF-8),
 * released by tf_transcript_options_destroy. A setter fails (TF_ERR_INVALID_ARGUMENT) only on a
 * NULL options; the encoding is checked when a file is read. */
typedef struct tf_transcript_options tf_transcript_options;

TF_API tf_status tf_transcript_options_create(tf_transcript_options **out);
/* Releases the options; NULL is allowed. */
TF_API void tf_transcript_options_destroy(tf_transcript_options *options);
/* Non-zero (the default) reads runs of Latin letters that spell Mandarin syllables ("ni3 hao3",
 * "nihao") as syllables; 0 reads them as letters or English words like any other Latin. */
TF_API tf_status tf_transcript_options_set_read_pinyin(tf_transcript_options *options, int read_pinyin);
/* Non-zero reads stage directions and speaker labels as text; 0 (the default) leaves them out with
 * a warning (docs/transcripts.md). */
TF_API tf_status tf_transcript_options_set_keep_directions(tf_transcript_options *options, int keep_directions);
/* A file's encoding when it has no byte order mark, as tf_load_transcript_with takes it (NULL or "":
 * UTF-8). Copied. Only files are decoded: tf_read_transcript_with_options reads UTF-8 whatever it says. */
TF_API tf_status tf_transcript_options_set_encoding(tf_transcript_options *options, const char *encoding);

/* tf_read_transcript read as `options` say (NULL: the defaults, as tf_read_transcript).
 * Errors: as tf_read_transcript. */
TF_API tf_status tf_read_transcript_with_options(const char *text, size_t length, const char *source_name,
                                                 const tf_transcript_options *options, tf_timeline **out);

/* tf_load_transcript read as `options` say (NULL: the defaults, as tf_load_transcript).
 * Errors: as tf_load_transcript_with. */
TF_API tf_status tf_load_transcript_with_options(const char *path, const tf_transcript_options *options,
                                                 tf_timeline **out);

/* A new empty timeline, to fill with tf_timeline_add_sentence / _add_syllable (a timeline read
 * from an `align` JSON document, say). Errors: TF_ERR_INVALID_ARGUMENT if out is NULL. */
TF_API tf_status tf_timeline_create(tf_timeline **out);

/* Releases a timeline. Accepts NULL. */
TF_API void tf_timeline_destroy(tf_timeline *timeline);

/* Appends a sentence: its text (UTF-8, copied) and times, seconds. Times are checked when the
 * timeline is used (simulation, animation), which names the sentence.
 * Errors: TF_ERR_INVALID_ARGUMENT if timeline or text is NULL. */
TF_API tf_status tf_timeline_add_sentence(tf_timeline *timeline, const char *text, double start_s,
                                          double end_s);

/* Appends a syllable of sentence `sentence_index`: its character and numbered pinyin (copied),
 * start and end, seconds; confidence 1, no final start, no pause after (see the setters below).
 * Errors: TF_ERR_INVALID_ARGUMENT if sentence_index names no sentence added so far, or an argument
 * is NULL. */
TF_API tf_status tf_timeline_add_syllable(tf_timeline *timeline, const char *text, const char *pinyin,
                                          size_t sentence_index, double start_s, double end_s);

/* Sets where syllable `index`'s final (vowel) starts, seconds; key frames use it.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or timeline is NULL. */
TF_API tf_status tf_timeline_set_syllable_final_start_s(tf_timeline *timeline, size_t index,
                                                        double final_start_s);

/* Sets syllable `index`'s confidence, 0..1.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range, the value is outside 0..1, or timeline
 * is NULL. */
TF_API tf_status tf_timeline_set_syllable_confidence(tf_timeline *timeline, size_t index,
                                                     double confidence);

/* Marks (non-zero) or clears (0) a pause the transcript marks after syllable `index` (，、：).
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or timeline is NULL. */
TF_API tf_status tf_timeline_set_syllable_pause_after(tf_timeline *timeline, size_t index,
                                                      int pause_after);

/* Sets the length of the audio, seconds. Errors: TF_ERR_INVALID_ARGUMENT if timeline is NULL. */
TF_API tf_status tf_timeline_set_duration_s(tf_timeline *timeline, double duration_s);

/* The length of the audio, seconds (0 before alignment).
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_timeline_duration_s(const tf_timeline *timeline, double *out_duration_s);

/* The number of sentences. Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_timeline_sentence_count(const tf_timeline *timeline, size_t *out_count);

/* Sentence `index`: its text (borrowed: valid while the timeline lives unmodified), start and end,
 * seconds. Any of out_text, out_start_s, out_end_s may be NULL.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or timeline is NULL. */
TF_API tf_status tf_timeline_sentence(const tf_timeline *timeline, size_t index, const char **out_text,
                                      double *out_start_s, double *out_end_s);

/* The number of syllables. Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_timeline_syllable_count(const tf_timeline *timeline, size_t *out_count);

/* Syllable `index`: its character and numbered pinyin (u-umlaut written v: "lv4"), both borrowed
 * (valid while the timeline lives unmodified), and the index of its sentence. Any out pointer may
 * be NULL. Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or timeline is NULL. */
TF_API tf_status tf_timeline_syllable(const tf_timeline *timeline, size_t index, const char **out_text,
                                      const char **out_pinyin, size_t *out_sentence_index);

/* Syllable `index`'s times, seconds: start (its initial consonant), end, and its final's start
 * when known (*out_has_final_start = 1; else 0 and *out_final_start_s is left unchanged). Any out
 * pointer may be NULL. Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or timeline is
 * NULL. */
TF_API tf_status tf_timeline_syllable_times(const tf_timeline *timeline, size_t index,
                                            double *out_start_s, double *out_end_s,
                                            int *out_has_final_start, double *out_final_start_s);

/* A syllable whose confidence is below this is one to check: its start may be more than 100 ms off
 * (talkface::kLowAlignmentConfidence). The confidence (0..1, not a probability) grows with the
 * evidence for the syllable's place: its sounds' fit, a change of spectrum where it starts, lengths
 * near their priors at the local pace, its neighbours' evidence, and whether the aligner's other
 * searches (its previous pass, the sounds weighed less with and without the spectral landmarks)
 * start it at the same frame, lenient alignment included, and how sure the search is of its start
 * (strict alignment: these in part averaged with its neighbours'); it is calibrated on the recording (the
 * fit's scatter in noise scaled to a clean recording's, then against the recording's median, more
 * so in a room or in noise), so the threshold holds per condition: on the benchmark's development
 * speech (a person and two voices made of the same speaker's) no condition (noise, rooms, music,
 * phone, fast speech) has more than 10% of its syllables within 100 ms under it (the person's
 * 2.3-8.4%, 4.7% pooled), and it catches 84% of those more than 100 ms off (held out: 1.7-6.7%,
 * 3.3% pooled, and 88%; the other voices 4.5-6.2% and 81-89%) (bench/README.md). `talkface align
 * --plot` draws such syllables in red. */
#define TF_LOW_ALIGNMENT_CONFIDENCE 0.5

/* Syllable `index`'s confidence (0..1; below TF_LOW_ALIGNMENT_CONFIDENCE: check it) and whether the
 * transcript marks a pause after it (1 or 0). Any out pointer may be NULL.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or timeline is NULL. */
TF_API tf_status tf_timeline_syllable_confidence(const tf_timeline *timeline, size_t index,
                                                 double *out_confidence, int *out_pause_after);

/* The number of warnings: what the reader skipped, each naming source:line:column, and after
 * alignment what the aligner says of the recording (a damaged or cut file, a header whose length
 * disagrees with its sound, each naming the file) and of the match (a finding of TF_CHECK_WARN, a
 * transcript with no Mandarin reading, which cannot be checked).
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_timeline_warning_count(const tf_timeline *timeline, size_t *out_count);

/* Warning `index`, borrowed: valid while the timeline lives unmodified.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or an argument is NULL. */
TF_API tf_status tf_timeline_warning(const tf_timeline *timeline, size_t index, const char **out_warning);

/* Marks (non-zero) or clears (0) that sentence `index` begins a paragraph of the transcript (a
 * blank line before it); the audio book's page keeps the paragraphs. tf_read_transcript sets it.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or timeline is NULL. */
TF_API tf_status tf_timeline_set_sentence_starts_paragraph(tf_timeline *timeline, size_t index,
                                                           int starts_paragraph);

/* Whether sentence `index` begins a paragraph (1) or not (0).
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or an argument is NULL. */
TF_API tf_status tf_timeline_sentence_starts_paragraph(const tf_timeline *timeline, size_t index,
                                                       int *out_starts_paragraph);

/* Marks (non-zero) or clears (0) that syllable `index` is part of a word no table reads (an English
 * word the dictionary lacks), which the aligner fits as any speech rather than as its pinyin
 * (TF_GENERIC_SPEECH_PINYIN, which only shapes the mouth). tf_read_transcript sets it.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or timeline is NULL. */
TF_API tf_status tf_timeline_set_syllable_generic_speech(tf_timeline *timeline, size_t index,
                                                         int generic_speech);

/* Whether syllable `index` is generic speech (1) or read from its pinyin (0): for "Zorblax", which
 * the English dictionary lacks, the reader makes "Zor" and "blax", each generic speech.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or an argument is NULL. */
TF_API tf_status tf_timeline_syllable_generic_speech(const tf_timeline *timeline, size_t index,
                                                     int *out_generic_speech);

/* The pinyin of a generic-speech syllable: a neutral open and close of the mouth
 * (talkface::kGenericSpeechPinyin). */
#define TF_GENERIC_SPEECH_PINYIN "de5"

/* The timeline as the timeline JSON (docs/timeline-format.md; the `align` document of SPEC
 * "Contracts", versioned), UTF-8: {"version":1, "sentences":[{"text","start","end"}],
 * "syllables":[{"text","pinyin","start","end","sentence","final_start" (only when known),
 * "confidence","pause_after","generic_speech" (only when true)}], "duration":s, "warnings":[...]},
 * numbers in shortest round-trip form, so that tf_timeline_from_json reads back the same timeline. Release *out_json with
 * tf_free; *out_len (if not NULL) is its length in bytes without the NUL.
 * Errors: TF_ERR_INVALID_ARGUMENT if timeline or out_json is NULL. */
TF_API tf_status tf_timeline_to_json(const tf_timeline *timeline, char **out_json, size_t *out_len);

/* How the timeline JSON is written (talkface::TimelineJsonOptions). Created by
 * tf_timeline_json_options_create with the defaults (times written), released by
 * tf_timeline_json_options_destroy. A setter fails (TF_ERR_INVALID_ARGUMENT) only on a NULL options. */
typedef struct tf_timeline_json_options tf_timeline_json_options;

TF_API tf_status tf_timeline_json_options_create(tf_timeline_json_options** out);
/* Releases the options; NULL is allowed. */
TF_API void tf_timeline_json_options_destroy(tf_timeline_json_options* options);
/* 0 leaves out every time and what the aligner measured (start, end, final_start, confidence,
 * duration), as `talkface syllables --json` does for a transcript not yet aligned; non-zero (the
 * default) writes them. */
TF_API tf_status tf_timeline_json_options_set_with_times(tf_timeline_json_options* options, int with_times);

/* tf_timeline_to_json written as `options` say (NULL: the defaults, as tf_timeline_to_json).
 * Errors: as tf_timeline_to_json. */
TF_API tf_status tf_timeline_to_json_with_options(const tf_timeline* timeline,
                                                  const tf_timeline_json_options* options, char** out_json,
                                                  size_t* out_len);

/* Reads the timeline JSON (`length` bytes of UTF-8) into a new timeline *out; source_name (may be
 * NULL: "<timeline>") names it in messages. Keys left out take their defaults (times 0).
 * Errors: TF_ERR_PARSE naming source:line:column and the item ("syllables[3].start") for text that
 *         is not JSON, a missing or mistyped key, a negative time, an end before its start, or a
 *         "version" newer than this build reads; TF_ERR_INVALID_ARGUMENT if json or out is NULL. */
TF_API tf_status tf_timeline_from_json(const char *json, size_t length, const char *source_name,
                                       tf_timeline **out);

/* tf_timeline_from_json of a file. Errors: TF_ERR_FILE naming the path if it cannot be read;
 * TF_ERR_PARSE as tf_timeline_from_json; TF_ERR_INVALID_ARGUMENT if path or out is NULL. */
TF_API tf_status tf_timeline_load_json(const char *path, tf_timeline **out);

/* 1 if `syllable` is a legal Mandarin syllable in numbered pinyin ("hang2", "lv4", "ma5"), else 0
 * (also for NULL). */
TF_API int tf_is_valid_pinyin(const char *syllable);

/* The most mouth shapes one syllable has. */
#define TF_MAX_SYLLABLE_SHAPES 4

/* The mouth shapes of one Mandarin syllable, in the order shown ("bo" -> m u o, "hao" -> h a u):
 * numbered or toneless pinyin, u-umlaut as v, "u:" or "ü". Writes the shapes into out[0 .. n-1] and
 * n (1..TF_MAX_SYLLABLE_SHAPES) into *out_count. With out NULL and capacity 0, only *out_count is
 * set (size first, then data).
 * Errors: TF_ERR_INVALID_ARGUMENT naming the syllable if it is not Mandarin, naming capacity if it
 * is below n (nothing is written then), or if pinyin or out_count is NULL. */
TF_API tf_status tf_syllable_mouth_shapes(const char *pinyin, tf_mouth_shape *out, size_t capacity,
                                          size_t *out_count);

/* The number of written forms the reader read by rule: numbers, dates, amounts, letters, English
 * words (docs/written-forms.md). Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_timeline_written_form_count(const tf_timeline *timeline, size_t *out_count);

/* Written form `index`: its text as the page shows it ("2026年"; borrowed, valid while the
 * timeline lives unmodified), the index of its first syllable and how many syllables it became
 * ("2026年": 5, 二零二六年). Any out pointer may be NULL.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or timeline is NULL. */
TF_API tf_status tf_timeline_written_form(const tf_timeline *timeline, size_t index, const char **out_text,
                                          size_t *out_first_syllable, size_t *out_syllable_count);

/* Appends a written form (text copied) covering syllables first_syllable ..
 * first_syllable + syllable_count - 1, after the forms already there (to rebuild a timeline).
 * Errors: TF_ERR_INVALID_ARGUMENT if timeline or text is NULL, text is empty, syllable_count is
 * 0, or the syllables are past the last one or start before the previous form's end. */
TF_API tf_status tf_timeline_add_written_form(tf_timeline *timeline, const char *text, size_t first_syllable,
                                              size_t syllable_count);

/* ---------------------------------------------------------------------------------------------
 * Speech alignment (SPEC step 4, thesis chapter 3): a recorded speech and its transcript become a
 * timeline with every sentence's and syllable's times (the `align` JSON of SPEC "Contracts").
 * ------------------------------------------------------------------------------------------- */

/* Reports progress: `fraction` of the whole job, 0..1, never decreasing and 1 only as the call
 * returns (work done again that no plan foresees, such as the recording read again at another
 * phase, fills the last 5% by halves), and the stage ("reading", "sentences", "syllables"; a
 * static string). Return 0 to go on, non-zero to cancel:
 * the call then fails with TF_ERR_CANCELLED and writes nothing. Called on the thread that called
 * tf_align_file / tf_align_samples, often enough to draw a progress bar. */
typedef int (*tf_progress_fn)(double fraction, const char *stage, void *user_data);

/* How the audio is cut into sentence utterances; values equal talkface::SentenceCutMode. */
typedef enum tf_sentence_cut_mode {
    /* The default: noise level and pause lengths are learned from the audio, and the transcript's
     * number of sentences picks the pauses. */
    TF_SENTENCE_CUT_AUTOMATIC = 0,
    /* Thesis Algorithm 3.1 from a pause the caller gives (tf_align_options_set_first_pause). */
    TF_SENTENCE_CUT_FIRST_PAUSE = 1
} tf_sentence_cut_mode;

/* Options of the aligner. Created by tf_align_options_create with the defaults (automatic sentence
 * cuts, c1 = 0.95, c2 = 1.45), released by tf_align_options_destroy. Each setter checks its value at
 * once and leaves the options unchanged on failure, so a tf_align_options is always valid. */
typedef struct tf_align_options tf_align_options;

/* New options with the defaults. Errors: TF_ERR_INVALID_ARGUMENT if out is NULL. */
TF_API tf_status tf_align_options_create(tf_align_options **out);

/* Releases options. Accepts NULL. */
TF_API void tf_align_options_destroy(tf_align_options *options);

/* Sets how sentences are cut. TF_SENTENCE_CUT_FIRST_PAUSE needs a pause set first; setting one with
 * tf_align_options_set_first_pause selects that mode by itself.
 * Errors: TF_ERR_INVALID_ARGUMENT naming sentence_cut for a value outside tf_sentence_cut_mode,
 * naming first_pause for TF_SENTENCE_CUT_FIRST_PAUSE before a pause is set, or for a NULL options. */
TF_API tf_status tf_align_options_set_sentence_cut(tf_align_options *options, tf_sentence_cut_mode mode);

/* Selects TF_SENTENCE_CUT_FIRST_PAUSE with the pause between the first two sentences, seconds from
 * the start of the audio (thesis Algorithm 3.1 step 1).
 * Errors: TF_ERR_INVALID_ARGUMENT naming first_pause unless 0 <= start_s < end_s (finite), or for a
 * NULL options. */
TF_API tf_status tf_align_options_set_first_pause(tf_align_options *options, double start_s, double end_s);

/* Sets c1 of Algorithm 3.1 step 3 (shortest pause, as a share of the first pause), 0.5..1.
 * Errors: TF_ERR_INVALID_ARGUMENT naming c1 if out of range, or for a NULL options. */
TF_API tf_status tf_align_options_set_c1(tf_align_options *options, double c1);

/* Sets c2 of Algorithm 3.1 step 4 (loudest silence, as a multiple of the first pause's peak), 1..1.5.
 * Errors: TF_ERR_INVALID_ARGUMENT naming c2 if out of range, or for a NULL options. */
TF_API tf_status tf_align_options_set_c2(tf_align_options *options, double c2);

/* What the aligner does when the audio does not sound like its transcript (a missing or extra
 * sentence, the wrong text, a sentence alone in its file whose text lacks its last words: speech
 * runs on 0.4 s or more past its last syllable that generic speech fits better); values equal
 * talkface::CheckMode. A finding names the sentence, its times and the evidence; a line of a few
 * syllables gives weak evidence, reported as a warning of the timeline in every mode (a line of one
 * sentence under 6 syllables a check finds only a little past its limit is aligned with the finding
 * as a warning, TF_CHECK_REFUSE too). */
typedef enum tf_check_mode {
    /* The default: strong evidence refuses the alignment (TF_ERR_ALIGNMENT), weak evidence on a
     * short line is a warning. */
    TF_CHECK_REFUSE = 0,
    /* Strong evidence becomes a warning of the timeline (tf_timeline_warning), aligned as with the
     * checks off. */
    TF_CHECK_WARN = 1,
    /* No checks. */
    TF_CHECK_OFF = 2
} tf_check_mode;

/* Sets what a transcript that does not match the audio does (TF_CHECK_REFUSE by default).
 * Errors: TF_ERR_INVALID_ARGUMENT naming check for a value outside tf_check_mode, or for a NULL
 * options. */
TF_API tf_status tf_align_options_set_check(tf_align_options *options, tf_check_mode mode);

/* Lenient alignment (non-zero) or not (0, the default): a transcript that differs from the speech
 * by a word or two is aligned rather than refused; each stretch of speech that does not say its
 * text is fitted as generic speech and reported (tf_timeline_mismatch and a warning), and the rest
 * is aligned as with a right text. The checks then refuse nothing.
 * Errors: TF_ERR_INVALID_ARGUMENT for a NULL options. */
TF_API tf_status tf_align_options_set_lenient(tf_align_options *options, int lenient);

/* The number of stretches where the speech does not say the text (lenient alignment only).
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_timeline_mismatch_count(const tf_timeline *timeline, size_t *out_count);

/* Mismatch `index`, in time order: its time span in seconds (start == end where the speech leaves
 * the text out), the first of the transcript's syllables it stands for and how many (0 where the
 * speech has words the transcript lacks), and the text the transcript expected there (borrowed,
 * valid while the timeline lives unmodified). Any out pointer may be NULL.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or timeline is NULL. */
TF_API tf_status tf_timeline_mismatch(const tf_timeline *timeline, size_t index, double *out_start_s,
                                      double *out_end_s, size_t *out_first_syllable, size_t *out_syllable_count,
                                      const char **out_expected_text);

/* The audio's loudness over mismatch `index`: *out_count values (borrowed in *out_values, valid
 * while the timeline lives unmodified; NULL where there are none), one per *out_step_s seconds
 * from its start (0.02 s; value k is the mean over [start + k step, start + (k + 1) step)), in
 * 0..1: 0 at or under the loudness the aligner takes for speech, 1 at the recording's loud speech
 * (its 95th percentile), linear in dB between, to 0.01. None where the stretch is an instant or
 * the timeline's source did not measure it. Over the stretch the mouth follows it (m under 0.1,
 * then z, n, and a from 0.67) instead of the syllables' shapes. Any out pointer may be NULL.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or timeline is NULL. */
TF_API tf_status tf_timeline_mismatch_loudness(const tf_timeline *timeline, size_t index, const double **out_values,
                                               size_t *out_count, double *out_step_s);

/* Aligns an audio file (WAV, FLAC, Ogg, MP3, AAC/M4A, Opus, AMR, AC-3, or the sound track of an MP4, MOV,
 * MKV, WebM, MPEG-TS or MPEG video; any rate, mono or stereo; of several sound tracks, the one that sounds like
 * speech, named in the timeline's warnings) with `transcript` (from tf_read_transcript /
 * tf_load_transcript) into a new timeline *out: the transcript's sentences and syllables with their times, seconds (syllable start = where its initial
 * consonant starts; final start and confidence set), and the audio's duration. The audio is read in
 * blocks: an hour of speech aligns in bounded memory. `options` NULL means the defaults; `progress`
 * may be NULL (user_data is passed to it untouched). *out is left unchanged on failure.
 * Thread safety: several alignments may run at once, also sharing transcript and options.
 * Errors: TF_ERR_FILE naming the path if it cannot be opened or read (truncated);
 *         TF_ERR_PARSE if it is not audio talkface reads; TF_ERR_INVALID_ARGUMENT if it is empty,
 *         the transcript has no syllables, or audio_path, transcript or out is NULL (named);
 *         TF_ERR_ALIGNMENT naming the file, the sentence and its times when audio and transcript do
 *         not match (a missing or extra sentence, the wrong text, a text that lacks its last
 *         words);
 *         TF_ERR_CANCELLED if progress returned non-zero. */
TF_API tf_status tf_align_file(const char *audio_path, const tf_timeline *transcript,
                               const tf_align_options *options, tf_progress_fn progress, void *user_data,
                               tf_timeline **out);

/* Aligns samples in memory as tf_align_file does: `frame_count` frames of `channel_count`
 * interleaved floats in -1..1 at `sample_rate_hz` (channels are mixed down to mono), borrowed for
 * the call only. The same audio gives the same timeline as tf_align_file.
 * Errors: TF_ERR_INVALID_ARGUMENT naming the argument: audio.frame_count if 0, audio.channel_count
 * or audio.sample_rate_hz if out of range (the message gives the range), samples, transcript or out
 * if NULL; otherwise as tf_align_file. */
TF_API tf_status tf_align_samples(const float *samples, size_t frame_count, int channel_count,
                                  int sample_rate_hz, const tf_timeline *transcript,
                                  const tf_align_options *options, tf_progress_fn progress,
                                  void *user_data, tf_timeline **out);

/* The picture of an alignment (thesis Figures 3.5 and 3.8) as a standalone SVG document: the audio
 * file's waveform (read again, in blocks), each sentence of `timeline` in one of two alternating
 * colours, each syllable's start marked and labelled with its text and pinyin. Release *out_svg with
 * tf_free; *out_len (if not NULL) is its length without the NUL.
 * Errors: TF_ERR_FILE or TF_ERR_PARSE naming the path if it cannot be read as audio;
 *         TF_ERR_INVALID_ARGUMENT if it has no frames or audio_path, timeline or out_svg is NULL. */
TF_API tf_status tf_alignment_plot_svg(const char *audio_path, const tf_timeline *timeline, char **out_svg,
                                       size_t *out_len);

/* Writes that picture to `svg_path` through a temporary file that is renamed: a failure leaves no
 * file behind. Errors: as tf_alignment_plot_svg, or TF_ERR_FILE naming svg_path. */
TF_API tf_status tf_write_alignment_plot_svg(const char *svg_path, const char *audio_path,
                                             const tf_timeline *timeline);

/* ---------------------------------------------------------------------------------------------
 * Expression simulation (SPEC step 5): blinks, eyebrow raises, head tilts, turns and nods drawn
 * from a seed (the same seed gives the same events on every platform), plus the caller's own.
 * ------------------------------------------------------------------------------------------- */

/* What an expression event does; values equal talkface::ExpressionEventKind. */
typedef enum tf_expression_event_kind {
    TF_EVENT_BLINK = 0,
    TF_EVENT_BROWS = 1,
    TF_EVENT_TILT = 2,
    TF_EVENT_TURN = 3,
    TF_EVENT_NOD = 4
} tf_expression_event_kind;

/* "blink", "brows", "tilt", "turn", "nod": a static string; NULL for a value outside the enum. */
TF_API const char *tf_expression_event_kind_name(tf_expression_event_kind kind);

/* Parses a name as tf_expression_event_kind_name writes it.
 * Errors: TF_ERR_INVALID_ARGUMENT listing the valid names, or for a NULL argument. */
TF_API tf_status tf_expression_event_kind_from_name(const char *name, tf_expression_event_kind *out);

/* One blink, eyebrow raise or head movement over [start_s, end_s], seconds from the start of the
 * audio. amount: blink, how far the lids close, 0..1; brows, the raise at its peak, 0..1; tilt
 * (gamma), turn (beta), nod (alpha, > 0 down): the angle reached, degrees, within
 * +-TF_MAX_POSE_ANGLE_DEG. A plain value: fixed for the major version. */
typedef struct tf_expression_event {
    tf_expression_event_kind kind;
    double start_s;
    double end_s;
    double amount;
} tf_expression_event;

/* How a caller's events combine with the simulated ones. */
typedef enum tf_user_event_mode {
    TF_EVENTS_ADD = 0,    /* simulated events overlapping a caller's event of their kind are dropped */
    TF_EVENTS_REPLACE = 1 /* every simulated event of a kind the caller gives is dropped */
} tf_user_event_mode;

/* The simulated events of a timeline and the caller's. Created by tf_expression_simulator_create
 * or tf_expression_simulator_create_with_style, released by tf_expression_simulator_destroy. */
typedef struct tf_expression_simulator tf_expression_simulator;

/* Simulates the events of `timeline` from `seed` in a style: "normal" (the thesis's numbers for a
 * normal pace; NULL means this) or "announcer" (TV news announcers: faster head movements).
 * The simulator keeps no reference to the timeline.
 * Errors: TF_ERR_INVALID_ARGUMENT for an unknown style (listing the valid names), a syllable whose
 * times are not finite or end before they start (named), or a NULL timeline or out. */
TF_API tf_status tf_expression_simulator_create(const tf_timeline *timeline, uint64_t seed,
                                                const char *style_name, tf_expression_simulator **out);

/* Releases a simulator. Accepts NULL. */
TF_API void tf_expression_simulator_destroy(tf_expression_simulator *simulator);

/* The distributions of the simulation and which kinds are simulated at all
 * (talkface::ExpressionStyle; the JSON of docs/style-format.md). Created by
 * tf_expression_style_create, _load or _from_json, released by tf_expression_style_destroy.
 *
 * Fields are read and written by name (the C++ member's name), so that new fields never change
 * this ABI:
 *   integer: blink_interval_shape (1..16)
 *   number (seconds): blink_interval_scale_s (> 0), nod_min_pause_s (>= 0)
 *   range (min, max): blink_duration_s, brows_interval_s, brows_duration_s, brows_amount (0..1),
 *     tilt_interval_s, tilt_duration_s, tilt_angle_deg, turn_interval_s, turn_duration_s,
 *     turn_angle_deg, nod_lead_s, nod_down_s, nod_up_s, nod_angle_deg; seconds (durations > 0) or
 *     degrees (0..TF_MAX_POSE_ANGLE_DEG)
 *   flag: is_blink_simulated, is_brows_simulated, is_tilt_simulated, is_turn_simulated,
 *     is_nod_simulated (also set by kind with tf_expression_style_set_simulated)
 * A setter checks the value at once: TF_ERR_INVALID_ARGUMENT naming the field if it is out of
 * range (the style is then unchanged), if the name is unknown (the message lists the fields of that
 * type) or names a field of another type. */
typedef struct tf_expression_style tf_expression_style;

/* A named style: "normal" (NULL means this) or "announcer".
 * Errors: TF_ERR_INVALID_ARGUMENT for an unknown name (listing the valid ones) or a NULL out. */
TF_API tf_status tf_expression_style_create(const char *base_name, tf_expression_style **out);

/* Reads a style JSON file (docs/style-format.md).
 * Errors: TF_ERR_FILE if it cannot be read; TF_ERR_PARSE naming file:line:column and the key for
 * text that is not JSON, an unknown key, a wrong type or a value out of range. */
TF_API tf_status tf_expression_style_load(const char *path, tf_expression_style **out);

/* The same from UTF-8 text; `source_name` names it in messages (NULL: "<string>").
 * Errors: TF_ERR_PARSE as tf_expression_style_load; TF_ERR_INVALID_ARGUMENT if json or out is NULL. */
TF_API tf_status tf_expression_style_from_json(const char *json, const char *source_name,
                                               tf_expression_style **out);

/* The style as JSON that tf_expression_style_from_json reads back: every field, one per line. The
 * same style always gives the same bytes. Release *out_json with tf_free; *out_len (if not NULL)
 * is its length without the NUL. Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_expression_style_to_json(const tf_expression_style *style, char **out_json,
                                             size_t *out_len);

/* Releases a style. Accepts NULL. */
TF_API void tf_expression_style_destroy(tf_expression_style *style);

/* The style's label ("normal", "announcer", "custom" ...), borrowed: valid while the style lives
 * unmodified. Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_expression_style_name(const tf_expression_style *style, const char **out_name);

/* A style's fields by their JSON keys (docs/style-format.md), by type: number, integer, range, flag.
 * A set that fails leaves the style as it was.
 * Errors: TF_ERR_INVALID_ARGUMENT for an unknown field (the message lists the type's fields), a field
 * of another type (naming it), a value a set puts out of range (naming the field), or a NULL
 * argument. */

/* Number fields. */
TF_API tf_status tf_expression_style_get_number(const tf_expression_style *style, const char *field,
                                                double *out_value);
TF_API tf_status tf_expression_style_set_number(tf_expression_style *style, const char *field, double value);

/* Integer fields. */
TF_API tf_status tf_expression_style_get_integer(const tf_expression_style *style, const char *field,
                                                 int *out_value);
TF_API tf_status tf_expression_style_set_integer(tf_expression_style *style, const char *field, int value);

/* Range fields: a uniform variable drawn from [min, max]. */
TF_API tf_status tf_expression_style_get_range(const tf_expression_style *style, const char *field,
                                               double *out_min, double *out_max);
TF_API tf_status tf_expression_style_set_range(tf_expression_style *style, const char *field, double min,
                                               double max);

/* Flag fields: 1 or 0 (any non-zero value sets the flag). */
TF_API tf_status tf_expression_style_get_flag(const tf_expression_style *style, const char *field,
                                              int *out_value);
TF_API tf_status tf_expression_style_set_flag(tf_expression_style *style, const char *field, int value);

/* Switches the simulation of one kind on (non-zero) or off (0): a kind switched off gets no
 * simulated events, and the other kinds' events stay the same for the same seed.
 * Errors: TF_ERR_INVALID_ARGUMENT for a kind outside tf_expression_event_kind or a NULL style. */
TF_API tf_status tf_expression_style_set_simulated(tf_expression_style *style, tf_expression_event_kind kind,
                                                   int is_simulated);

/* Simulates the events of `timeline` from `seed` in a style of the caller's (copied: later changes
 * to it do not reach the simulator). The simulator keeps no reference to the timeline.
 * Errors: TF_ERR_INVALID_ARGUMENT naming a style field out of range, a syllable whose times are
 * not finite or end before they start, or for a NULL argument. */
TF_API tf_status tf_expression_simulator_create_with_style(const tf_timeline *timeline, uint64_t seed,
                                                           const tf_expression_style *style,
                                                           tf_expression_simulator **out);

/* A copy of the style a simulator was made with; release it with tf_expression_style_destroy.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_expression_simulator_style(const tf_expression_simulator *simulator,
                                               tf_expression_style **out);

/* The end of the simulated time, seconds (the later of the timeline's duration and its last end).
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_expression_simulator_duration_s(const tf_expression_simulator *simulator,
                                                    double *out_duration_s);

/* The number of events in effect (simulated and the caller's), sorted by start time, then kind.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_expression_simulator_event_count(const tf_expression_simulator *simulator,
                                                     size_t *out_count);

/* Event `index` in effect, copied into *out.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or an argument is NULL. */
TF_API tf_status tf_expression_simulator_event(const tf_expression_simulator *simulator, size_t index,
                                               tf_expression_event *out);

/* Sets the caller's `count` events (copied; any order; replacing any set before) and combines them
 * with the simulated ones as `mode` says. count 0 (events may then be NULL) restores the simulated
 * events.
 * Errors: TF_ERR_INVALID_ARGUMENT naming the event (index, kind, times) if a time is not finite or
 * negative, it ends before it starts, an amount is out of range, or two events of one kind overlap
 * (both named); for a bad mode or a NULL argument. The simulator is then unchanged. */
TF_API tf_status tf_expression_simulator_set_user_events(tf_expression_simulator *simulator,
                                                         const tf_expression_event *events, size_t count,
                                                         tf_user_event_mode mode);

/* The head pose at a time, degrees (0 before the first event).
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_expression_simulator_pose_at(const tf_expression_simulator *simulator, double time_s,
                                                 double *out_alpha_deg, double *out_beta_deg,
                                                 double *out_gamma_deg);

/* Blinks (image-left and image-right eye) and eyebrow raise at a time, 0..1; smile stays 0.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_expression_simulator_expression_at(const tf_expression_simulator *simulator,
                                                       double time_s, double *out_blink_left,
                                                       double *out_blink_right, double *out_smile,
                                                       double *out_brows);

/* ---------------------------------------------------------------------------------------------
 * Animation (SPEC steps 6 and 7, thesis 5.4): a timeline, a face and a simulator become every
 * frame, and the key frames export as JSON and TSV for other animation tools.
 * ------------------------------------------------------------------------------------------- */

/* How the lips move. Created by tf_lip_sync_options_create with the defaults (25 fps, rest in pauses
 * of 0.3 s or more, 0.1 s rest transitions, linear interpolation, at most 8.75 MNS0 per second,
 * the thesis's onset table);
 * released by tf_lip_sync_options_destroy. Values are checked when animating, which names them. */
typedef struct tf_lip_sync_options tf_lip_sync_options;

/* How the mouth moves between two key frames. */
typedef enum tf_mouth_interpolation {
    TF_INTERPOLATION_LINEAR = 0, /* straight lines, as the thesis (5.4) */
    TF_INTERPOLATION_SMOOTH = 1  /* cosine ease in and out */
} tf_mouth_interpolation;

/* New options with the defaults. Errors: TF_ERR_INVALID_ARGUMENT if out is NULL. */
TF_API tf_status tf_lip_sync_options_create(tf_lip_sync_options **out);

/* Releases options. Accepts NULL. */
TF_API void tf_lip_sync_options_destroy(tf_lip_sync_options *options);

/* Sets the frames per second. Errors: TF_ERR_INVALID_ARGUMENT if options is NULL. */
TF_API tf_status tf_lip_sync_options_set_fps(tf_lip_sync_options *options, double fps);

/* Sets the shortest gap between syllables in which the mouth rests, and how long it takes to reach
 * and leave the rest, seconds. Errors: TF_ERR_INVALID_ARGUMENT if options is NULL. */
TF_API tf_status tf_lip_sync_options_set_rest(tf_lip_sync_options *options, double rest_min_pause_s,
                                              double rest_transition_s);

/* Sets one row of the onset table (thesis 5.3): when the later shapes of a syllable of
 * `shape_count` shapes (2, 3 or 4) start, as fractions of the syllable's duration; `fractions`
 * holds shape_count - 1 values (copied) that must rise strictly inside (0, 1), which animating
 * checks and names (e.g. "ShapeOnsetTable::three_shapes"). The defaults: 2 shapes 0.1905;
 * 3 shapes 0.1688, 0.6025; 4 shapes 0.2847, 0.5297, 0.7412.
 * Errors: TF_ERR_INVALID_ARGUMENT if shape_count is not 2, 3 or 4, or an argument is NULL. */
TF_API tf_status tf_lip_sync_options_set_onsets(tf_lip_sync_options *options, size_t shape_count,
                                                const double *fractions);

/* Copies one row of the onset table (shape_count - 1 values) into out_fractions.
 * Errors: TF_ERR_INVALID_ARGUMENT if shape_count is not 2, 3 or 4, or an argument is NULL. */
TF_API tf_status tf_lip_sync_options_get_onsets(const tf_lip_sync_options *options, size_t shape_count,
                                                double *out_fractions);

/* Sets how the mouth moves between key frames.
 * Errors: TF_ERR_INVALID_ARGUMENT for a value outside tf_mouth_interpolation or a NULL options. */
TF_API tf_status tf_lip_sync_options_set_interpolation(tf_lip_sync_options *options,
                                                       tf_mouth_interpolation interpolation);

/* Sets the speed limit of the mouth control points, MNS0 (mouth-nose separation) per second.
 * Errors: TF_ERR_INVALID_ARGUMENT if options is NULL. */
TF_API tf_status tf_lip_sync_options_set_max_speed_mns0_per_s(tf_lip_sync_options *options,
                                                             double max_speed_mns0_per_s);

/* A finished animation: mouth key frames, the events in effect and every frame's state. Created by
 * tf_animate, released by tf_animation_destroy. */
typedef struct tf_animation tf_animation;

/* Builds every frame of `timeline` for the neutral `face`: lips from the syllables, pose, blinks
 * and brows from `simulator` (its events in effect now; later changes to it do not reach the
 * animation). `options` NULL means the defaults. Frame i shows time i / fps.
 * Errors: TF_ERR_INVALID_ARGUMENT naming the syllable (index, pinyin, times) whose pinyin is not
 * Mandarin or whose times are wrong, or the option that is out of range, or for a NULL face,
 * timeline, simulator or out. */
TF_API tf_status tf_animate(const tf_face_model *face, const tf_timeline *timeline,
                            const tf_expression_simulator *simulator, const tf_lip_sync_options *options,
                            tf_animation **out);

/* Releases an animation. Accepts NULL. */
TF_API void tf_animation_destroy(tf_animation *animation);

/* Frames per second and length, seconds. Either out pointer may be NULL.
 * Errors: TF_ERR_INVALID_ARGUMENT if animation is NULL. */
TF_API tf_status tf_animation_timing(const tf_animation *animation, double *out_fps, double *out_duration_s);

/* The number of frames. Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_animation_frame_count(const tf_animation *animation, size_t *out_count);

/* Frame `index`'s head pose, degrees.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or an argument is NULL. */
TF_API tf_status tf_animation_frame_pose(const tf_animation *animation, size_t index, double *out_alpha_deg,
                                         double *out_beta_deg, double *out_gamma_deg);

/* Frame `index`'s expression amounts, 0..1.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or an argument is NULL. */
TF_API tf_status tf_animation_frame_expression(const tf_animation *animation, size_t index,
                                               double *out_blink_left, double *out_blink_right,
                                               double *out_smile, double *out_brows);

/* Frame `index`'s mouth control points (up 8.9, down 8.2, left 8.4, right 8.3), image pixels.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or an argument is NULL. */
TF_API tf_status tf_animation_frame_mouth_controls(const tf_animation *animation, size_t index,
                                                   double out_up[2], double out_down[2], double out_left[2],
                                                   double out_right[2]);

/* Frame `index` as a new face state: pass it with the animation's face to tf_project_face for the
 * frame's points, or to tf_render_svg for its picture.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or an argument is NULL. */
TF_API tf_status tf_animation_frame_state(const tf_animation *animation, size_t index, tf_face_state **out);

/* The number of mouth key frames. Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_animation_mouth_key_frame_count(const tf_animation *animation, size_t *out_count);

/* Mouth key frame `index`: the time the mouth reaches `shape`, seconds, and the index of the
 * syllable it belongs to (*out_has_syllable = 1), or a rest (*out_has_syllable = 0 and
 * *out_syllable_index left unchanged). Any out pointer may be NULL.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or animation is NULL. */
TF_API tf_status tf_animation_mouth_key_frame(const tf_animation *animation, size_t index, double *out_time_s,
                                              tf_mouth_shape *out_shape, int *out_has_syllable,
                                              size_t *out_syllable_index);

/* The number of expression events the animation was made with.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_animation_event_count(const tf_animation *animation, size_t *out_count);

/* Event `index` of the animation, copied into *out.
 * Errors: TF_ERR_INVALID_ARGUMENT if index is out of range or an argument is NULL. */
TF_API tf_status tf_animation_event(const tf_animation *animation, size_t index, tf_expression_event *out);

/* The key frames as JSON, one item per line, times in seconds with at most 3 decimals:
 * {"fps":25,"duration":s, "mouth":[{"time":s,"shape":"a","syllable":k}], "events":[{"kind":"blink",
 * "start":s,"end":s,"amount":x}]}: the animation's frame rate and length first, "syllable":null for
 * a rest. The same animation always gives the same bytes.
 * Release *out_json with tf_free; *out_len (if not NULL) is its length without the NUL.
 * Errors: TF_ERR_INVALID_ARGUMENT if animation or out_json is NULL. */
TF_API tf_status tf_animation_key_frames_json(const tf_animation *animation, char **out_json,
                                              size_t *out_len);

/* The mouth key frames as "time<TAB>shape" lines (no header). Release *out_tsv with tf_free.
 * Errors: TF_ERR_INVALID_ARGUMENT if animation or out_tsv is NULL. */
TF_API tf_status tf_animation_key_frames_tsv(const tf_animation *animation, char **out_tsv,
                                             size_t *out_len);

/* ---------------------------------------------------------------------------------------------
 * The animation as SVG and the web page around it (SPEC step 7-8, thesis 6.3.2 and chapter 7).
 * ------------------------------------------------------------------------------------------- */

/* How an animation becomes SVG; values equal talkface::AnimationEncoding. */
typedef enum tf_animation_encoding {
    /* The default: the face drawn once, each moving element animated by SMIL <animate> between
     * key frames (within 0.3 px of every frame): small files. */
    TF_ENCODING_KEYFRAMES = 0,
    /* Thesis 6.3.2: one group per frame, shown in turn by <set>. Exact, large. */
    TF_ENCODING_FRAMES = 1
} tf_animation_encoding;

/* A standalone SVG document that plays `animation` of `face` from document time 0 (root class
 * "tf-animation"). `options` NULL means the default drawing; `progress` may be NULL.
 * Release *out_svg with tf_free; *out_len (if not NULL) is its length without the NUL.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL, the encoding is unknown or a frame
 * cannot be drawn; TF_ERR_CANCELLED if progress returned non-zero. */
TF_API tf_status tf_render_animation_svg(const tf_face_model *face, const tf_animation *animation,
                                         const tf_svg_options *options, tf_animation_encoding encoding,
                                         tf_progress_fn progress, void *user_data, char **out_svg,
                                         size_t *out_len);

/* tf_render_animation_svg written to `path` through a temporary file and a rename.
 * Errors: as tf_render_animation_svg; TF_ERR_FILE if the file cannot be written. */
TF_API tf_status tf_write_animation_svg(const tf_face_model *face, const tf_animation *animation,
                                        const tf_svg_options *options, tf_animation_encoding encoding,
                                        const char *path);

/* How an animation becomes SVG (talkface::SvgAnimationOptions), for the _with_options forms of the
 * two calls above. Created by tf_svg_animation_options_create with the defaults (TF_ENCODING_KEYFRAMES,
 * 0.3 px), released by tf_svg_animation_options_destroy. A setter fails (TF_ERR_INVALID_ARGUMENT)
 * only on a NULL options and where its comment says; the tolerance is checked when the animation is
 * drawn. */
typedef struct tf_svg_animation_options tf_svg_animation_options;

TF_API tf_status tf_svg_animation_options_create(tf_svg_animation_options** out);
/* Releases the options; NULL is allowed. */
TF_API void tf_svg_animation_options_destroy(tf_svg_animation_options* options);
/* Errors: TF_ERR_INVALID_ARGUMENT if options is NULL or the encoding is unknown. */
TF_API tf_status tf_svg_animation_options_set_encoding(tf_svg_animation_options* options,
                                                       tf_animation_encoding encoding);
/* TF_ENCODING_KEYFRAMES: the largest distance, in the face's pixels, between a coordinate the
 * browser interpolates and the same coordinate of the frame at that time (a finite number > 0;
 * 0.3, the default, is below what an eye sees at the face's own size). Larger: smaller files. */
TF_API tf_status tf_svg_animation_options_set_tolerance_px(tf_svg_animation_options* options,
                                                           double tolerance_px);

/* tf_render_animation_svg written as `animation_options` say (NULL: the defaults).
 * Errors: as tf_render_animation_svg; TF_ERR_INVALID_ARGUMENT naming "tolerance_px" if it is not
 * a finite number > 0. */
TF_API tf_status tf_render_animation_svg_with_options(const tf_face_model* face,
                                                      const tf_animation* animation,
                                                      const tf_svg_options* options,
                                                      const tf_svg_animation_options* animation_options,
                                                      tf_progress_fn progress, void* user_data,
                                                      char** out_svg, size_t* out_len);

/* tf_write_animation_svg written as `animation_options` say (NULL: the defaults).
 * Errors: as tf_render_animation_svg_with_options; TF_ERR_FILE if the file cannot be written. */
TF_API tf_status tf_write_animation_svg_with_options(const tf_face_model* face, const tf_animation* animation,
                                                     const tf_svg_options* options,
                                                     const tf_svg_animation_options* animation_options,
                                                     const char* path);

/* The animation as one Lottie document (JSON, as lottie-web reads it; lottie-android, lottie-ios
 * and rlottie play it): the drawing of tf_render_animation_svg (`options` NULL: the default) as
 * Lottie shape layers, every moving number animated between key frames, linear between them,
 * within tolerance_px (> 0; 0.3 is C++'s default) of every frame. Lottie carries no sound: a page
 * plays the recording beside it and sets the animation's time from the audio's clock.
 * `progress` may be NULL. Release *out_json with tf_free; *out_len (if not NULL) is its length
 * without the NUL.
 * Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL, tolerance_px is not > 0 or a frame
 * cannot be drawn; TF_ERR_CANCELLED if progress returned non-zero. */
TF_API tf_status tf_render_animation_lottie(const tf_face_model *face, const tf_animation *animation,
                                            const tf_svg_options *options, double tolerance_px,
                                            tf_progress_fn progress, void *user_data, char **out_json,
                                            size_t *out_len);

/* tf_render_animation_lottie written to `path` through a temporary file and a rename.
 * Errors: as tf_render_animation_lottie; TF_ERR_FILE if the file cannot be written. */
TF_API tf_status tf_write_animation_lottie(const tf_face_model *face, const tf_animation *animation,
                                           const tf_svg_options *options, double tolerance_px, const char *path);

/* What a web page is for; values equal talkface::WebPageApp. */
typedef enum tf_web_page_app {
    TF_PAGE_PLAIN = 0,      /* the talking face and the audio controls */
    TF_PAGE_ANNOUNCER = 1,  /* the face placed on a stage over a colour or an image (thesis 7.2) */
    TF_PAGE_AUDIOBOOK = 2   /* title, text with the spoken sentence highlighted, links, face (7.3) */
} tf_web_page_app;

/* Options of a web page. Created by tf_web_page_options_create with the defaults (plain page,
 * key frames, audio compressed and embedded, an 800 x 450 stage), released by tf_web_page_options_destroy.
 * A setter fails (TF_ERR_INVALID_ARGUMENT) only on a NULL options and where its comment says; the values
 * are checked when the page is built (tf_build_web_page). */
typedef struct tf_web_page_options tf_web_page_options;

TF_API tf_status tf_web_page_options_create(tf_web_page_options **out);
/* Releases the options; NULL is allowed. */
TF_API void tf_web_page_options_destroy(tf_web_page_options *options);
/* Errors: TF_ERR_INVALID_ARGUMENT if options is NULL or app is not a tf_web_page_app. */
TF_API tf_status tf_web_page_options_set_app(tf_web_page_options *options, tf_web_page_app app);
/* The page's title, UTF-8 (NULL or "": the first sentence, its first 30 characters and an ellipsis
   when longer). Escaped in the page. */
TF_API tf_status tf_web_page_options_set_title(tf_web_page_options *options, const char *title);
/* Appends a link of the audio book: its text and URL (http:, https:, mailto: or relative; other
 * schemes fail when the page is built). Errors: TF_ERR_INVALID_ARGUMENT if an argument is NULL. */
TF_API tf_status tf_web_page_options_add_link(tf_web_page_options *options, const char *text, const char *url);
/* Errors: TF_ERR_INVALID_ARGUMENT if options is NULL or the encoding is unknown. */
TF_API tf_status tf_web_page_options_set_encoding(tf_web_page_options *options, tf_animation_encoding encoding);
/* The animation's tolerance, as tf_svg_animation_options_set_tolerance_px (0.3 by default). */
TF_API tf_status tf_web_page_options_set_tolerance_px(tf_web_page_options* options, double tolerance_px);
/* How a web page carries its audio; values equal talkface::WebPageAudio. */
typedef enum tf_web_page_audio {
    TF_PAGE_AUDIO_COMPRESSED = 0,  /* embedded as Opus in WebM, mono, for speech (the default) */
    TF_PAGE_AUDIO_ORIGINAL = 1,    /* embedded as the audio file's own bytes */
    TF_PAGE_AUDIO_LINK = 2         /* linked: the audio file must stay beside the page */
} tf_web_page_audio;

/* How the page carries its audio. bitrate_bps: TF_PAGE_AUDIO_COMPRESSED's Opus bit rate, 6000 to
 * 128000 (0: 11000, wideband speech), checked when the page is built. url: TF_PAGE_AUDIO_LINK's
 * link, relative to the page (NULL or "": the audio file's name).
 * Errors: TF_ERR_INVALID_ARGUMENT if options is NULL or audio is not a tf_web_page_audio. */
TF_API tf_status tf_web_page_options_set_audio(tf_web_page_options *options, tf_web_page_audio audio,
                                               int bitrate_bps, const char *url);
/* Announcer: the stage's size in CSS pixels (its shape, and the pixels of the face's placement: the
 * page shows it as large as the window lets it be), its colour, and a background image file (PNG,
 * JPEG, GIF, WebP or SVG, embedded; NULL for none). */
TF_API tf_status tf_web_page_options_set_stage(tf_web_page_options *options, int width_px, int height_px,
                                               tf_rgb colour, const char *image_path);
/* Announcer: where the face's rotation origin O (the neck) stands on the stage, pixels (origin_xy
 * NULL: the bottom centre), and its eye distance d there (0: as large as fits the stage). */
TF_API tf_status tf_web_page_options_set_face_placement(tf_web_page_options *options, const double origin_xy[2],
                                                        double d_px);

/* The web page, one self-contained UTF-8 HTML file: the animation of `face` inline, the audio at
 * `audio_path` (.ogg .wav .flac .mp3 ...) embedded or linked, and a script that makes the audio's
 * clock drive the face. `timeline` gives the sentences (the aligned one the animation was made
 * from). `svg_options` and `page_options` may be NULL (defaults); `progress` may be NULL.
 * Release *out_html with tf_free.
 * Errors: TF_ERR_INVALID_ARGUMENT for a NULL argument, an option out of range, a refused link;
 * TF_ERR_FILE if the audio or the image cannot be read; TF_ERR_CANCELLED. */
TF_API tf_status tf_build_web_page(const tf_face_model *face, const tf_svg_options *svg_options,
                                   const tf_animation *animation, const tf_timeline *timeline,
                                   const char *audio_path, const tf_web_page_options *page_options,
                                   tf_progress_fn progress, void *user_data, char **out_html, size_t *out_len);

/* tf_build_web_page written to `path` through a temporary file and a rename: a failure never leaves
 * half a page. Errors: as tf_build_web_page; TF_ERR_FILE if the page cannot be written. */
TF_API tf_status tf_write_web_page(const tf_face_model *face, const tf_svg_options *svg_options,
                                   const tf_animation *animation, const tf_timeline *timeline,
                                   const char *audio_path, const tf_web_page_options *page_options,
                                   const char *path);

/* ---------------------------------------------------------------------------------------------
 * Timing exports and imports (issue 15, docs/timing-formats.md): the timing of a speech for the
 * tools animators use, and timings from theirs instead of the aligner.
 * ------------------------------------------------------------------------------------------- */

/* The export of an aligned timeline and its animation (tf_animate) in `format`: "rhubarb-tsv",
 * "rhubarb-json", "rhubarb-xml", "moho", "live2d", "textgrid", "srt" or "vtt", spanning 0 to the
 * timeline's duration. audio_path (may be NULL) goes into Rhubarb's metadata.soundFile. Release
 * *out_document with tf_free; *out_len (if not NULL) is its length without the NUL.
 * Errors: TF_ERR_INVALID_ARGUMENT naming an unknown format (and listing the formats), a duration
 * that is not positive, or a NULL timeline, animation, format or out_document. */
TF_API tf_status tf_export_to_string(const tf_timeline *timeline, const tf_animation *animation, const char *format,
                                     const char *audio_path, char **out_document, size_t *out_len);

/* tf_export_to_string written to `path` atomically; format NULL or "" takes it from the suffix
 * (.tsv .xml .dat .motion3.json .TextGrid .srt .vtt).
 * Errors: as tf_export_to_string; TF_ERR_INVALID_ARGUMENT for a suffix that names no format;
 * TF_ERR_FILE naming the path (the file is then left as it was). */
TF_API tf_status tf_export_to_file(const char *path, const tf_timeline *timeline, const tf_animation *animation,
                                   const char *format, const char *audio_path);

/* The transcript (tf_read_transcript) timed by a timing document instead of the aligner, into a
 * new timeline *out: format "textgrid" (a syllables or words tier), "srt", "vtt", "words-json"
 * (a list of {"text","start","end"}), "timeline-json", or "json" (either JSON). duration_s is the
 * audio's length (0: not checked). source_name (may be NULL) names the document in messages.
 * Errors: TF_ERR_PARSE naming source:line for a malformed document, times out of order or past
 * duration_s, or a text that parts from the transcript (the first place they part);
 * TF_ERR_INVALID_ARGUMENT for an unknown format or a NULL argument. */
TF_API tf_status tf_read_timing_string(const char *text, size_t length, const char *format,
                                       const tf_timeline *transcript, double duration_s, const char *source_name,
                                       tf_timeline **out);

/* tf_read_timing_string of a file; format NULL or "" takes it from the suffix.
 * Errors: TF_ERR_FILE naming the path; as tf_read_timing_string. */
TF_API tf_status tf_read_timing_file(const char *path, const tf_timeline *transcript, double duration_s,
                                     const char *format, tf_timeline **out);

/* The timeline in an import format ("textgrid", "srt", "vtt", "words-json", "timeline-json"), so
 * that tf_read_timing_string gives its times back. Release *out_document with tf_free.
 * Errors: TF_ERR_INVALID_ARGUMENT for an unknown format or a NULL argument. */
TF_API tf_status tf_write_timing_string(const tf_timeline *timeline, const char *format, char **out_document,
                                        size_t *out_len);

/* The transcript spoken in audio_path, timed by the timing file instead of the aligner alone (what
 * `--timing FILE` does): word and syllable timings are read as they are; subtitle cues that give
 * sentence times only pin the aligner (each sentence is searched only inside its cues; the models
 * are learned, and a wrong text refused, over the whole recording), cues that time every syllable
 * (WebVTT cue timestamps, as the vtt export writes) are read as they are. format NULL or "" takes
 * it from the suffix.
 * Errors: as tf_read_timing_file and tf_align_file. */
TF_API tf_status tf_time_transcript(const char *timing_path, const char *audio_path, const tf_timeline *transcript,
                                    const char *format, tf_timeline **out);

/* tf_time_transcript, the aligner that subtitle cues pin taking `options` (NULL: the defaults):
 * its check mode decides what a wrong text does, and with tf_align_options_set_lenient a stretch
 * inside the cues that does not say its text is reported (tf_timeline_mismatch) rather than
 * refused. `progress` may be NULL (user_data is passed to it untouched).
 * Errors: as tf_time_transcript; TF_ERR_INVALID_ARGUMENT naming lenient when the options are
 * lenient and the file times every syllable itself (textgrid, words-json, timeline-json, or cues
 * with a timestamp per syllable): nothing is aligned, so nothing could be found not to match;
 * TF_ERR_CANCELLED if progress returned non-zero. */
TF_API tf_status tf_time_transcript_with_options(const char *timing_path, const char *audio_path,
                                                 const tf_timeline *transcript, const char *format,
                                                 const tf_align_options *options, tf_progress_fn progress,
                                                 void *user_data, tf_timeline **out);

/* ---------------------------------------------------------------------------------------------
 * Video (talkface::VideoWriter, video_writer.hpp): frames of RGBA pixels and a speech encoded
 * through FFmpeg's libraries, the kind of file told by the extension. Written to a temporary file
 * beside the output and renamed by tf_video_writer_finish: a writer destroyed unfinished leaves
 * no output. Encoders are found by name in the FFmpeg the process loaded. */

/* The kinds of video file; values equal talkface::VideoFormat. */
typedef enum tf_video_format {
    TF_VIDEO_MP4 = 0,          /* .mp4: H.264 (yuv420p) + AAC, index in front */
    TF_VIDEO_WEBM = 1,         /* .webm: VP9 + Opus; transparent: with an alpha channel */
    TF_VIDEO_WEBP = 2,         /* .webp: animated WebP, looping, no sound */
    TF_VIDEO_PNG_SEQUENCE = 3, /* .png: OUT-000000.png, OUT-000001.png, ..., no sound */
    TF_VIDEO_GIF = 4           /* .gif: animated GIF, looping, no sound; one palette from the first frames, 1..50 fps */
} tf_video_format;

/* The format of an output path by its extension (either case).
 * Errors: TF_ERR_INVALID_ARGUMENT for an unknown extension (the message names it) or a NULL argument. */
TF_API tf_status tf_video_format_from_path(const char *path, tf_video_format *out_format);

/* How a video is encoded. Created by tf_video_options_create with the defaults (1280 x 720, 30 fps,
 * the format's default quality, opaque), released by tf_video_options_destroy. Values are checked
 * when a writer is opened (or by tf_check_video_options): a setter fails (TF_ERR_INVALID_ARGUMENT)
 * only on a NULL options. */
typedef struct tf_video_options tf_video_options;

TF_API tf_status tf_video_options_create(tf_video_options **out);
/* Releases the options; NULL is allowed. */
TF_API void tf_video_options_destroy(tf_video_options *options);
/* Frame size in pixels: 2..7680 (the longer side) by 2..4320 (the shorter); even for .mp4 and .webm. */
TF_API tf_status tf_video_options_set_size(tf_video_options *options, int width_px, int height_px);
/* Frames per second, 1..120 (1..50 for .gif). */
TF_API tf_status tf_video_options_set_fps(tf_video_options *options, double fps);
/* Constant quality, lower is better: H.264 0..51, VP9 0..63; -1 the default (20, 32). */
TF_API tf_status tf_video_options_set_crf(tf_video_options *options, int crf);
/* Non-zero keeps the frames' alpha channel (.webm, .webp, .gif, .png only; .gif: alpha under half
 * is transparent). */
TF_API tf_status tf_video_options_set_transparent(tf_video_options *options, int transparent);
/* Checks options for an output at path without creating anything. options may be NULL (defaults).
 * Errors: TF_ERR_INVALID_ARGUMENT naming the option (width_px, height_px, fps, crf, transparent)
 * or the extension, with what was expected. */
TF_API tf_status tf_check_video_options(const char *path, const tf_video_options *options);

/* A video being written. Opened by tf_video_writer_open, released by tf_video_writer_destroy. */
typedef struct tf_video_writer tf_video_writer;

/* Opens `path` (options may be NULL: the defaults).
 * Errors: TF_ERR_INVALID_ARGUMENT as tf_check_video_options, or if the system's FFmpeg lacks the
 * format's encoder (the message names it); TF_ERR_FILE if no temporary file can be made beside path. */
TF_API tf_status tf_video_writer_open(const char *path, const tf_video_options *options, tf_video_writer **out);
/* Releases the writer; an unfinished one removes its temporary file. NULL is allowed. */
TF_API void tf_video_writer_destroy(tf_video_writer *writer);
/* The sound, from frame 0: frame_count frames of channel_count interleaved floats in -1..1 (mixed
 * down to mono), read while frames are written: they must stay valid until tf_video_writer_finish.
 * .webp and .png ignore it. Before the first frame, at most once.
 * Errors: TF_ERR_INVALID_ARGUMENT for malformed audio, a second call or a call after a frame. */
TF_API tf_status tf_video_writer_add_audio(tf_video_writer *writer, const float *samples, size_t frame_count,
                                           int channel_count, int sample_rate_hz);
/* The same from an audio file (WAV, FLAC, OGG ...). Errors: TF_ERR_FILE, TF_ERR_PARSE, as above. */
TF_API tf_status tf_video_writer_add_audio_file(tf_video_writer *writer, const char *audio_path);
/* Appends a frame: height rows of width straight-alpha RGBA pixels (the options' size), row y at
 * rgba + y * stride_bytes. Frame k is shown at k / fps.
 * Errors: TF_ERR_INVALID_ARGUMENT for NULL or a stride < 4 * width; TF_ERR_FILE if writing fails. */
TF_API tf_status tf_video_writer_write_frame(tf_video_writer *writer, const uint8_t *rgba, size_t stride_bytes);
/* The frames written so far. Errors: TF_ERR_INVALID_ARGUMENT for a NULL argument. */
TF_API tf_status tf_video_writer_frame_count(const tf_video_writer *writer, size_t *out_count);
/* Encodes the rest of the sound, closes the file and renames it into place; call once.
 * Errors: TF_ERR_INVALID_ARGUMENT if no frame was written or it was finished; TF_ERR_FILE. */
TF_API tf_status tf_video_writer_finish(tf_video_writer *writer);

/* How the face looks in a video (talkface::FaceVideoOptions without its VideoOptions). Created by
 * tf_video_look_create with the defaults (the announcer over #1d3b5c), released by tf_video_look_destroy.
 * A setter fails (TF_ERR_INVALID_ARGUMENT) only on a NULL look and where its comment says; the values
 * are checked when the video is made (tf_render_video). */
typedef struct tf_video_look tf_video_look;

TF_API tf_status tf_video_look_create(tf_video_look **out);
/* Releases it; NULL is allowed. */
TF_API void tf_video_look_destroy(tf_video_look *look);
/* Where the face stands, as in tf_frame_options_set_layout (the announcer: where the announcer page
 * stands it for the same animation).
 * Errors: TF_ERR_INVALID_ARGUMENT if look is NULL or layout is not a tf_frame_layout. */
TF_API tf_status tf_video_look_set_layout(tf_video_look *look, tf_frame_layout layout);
/* The background: a colour (NULL: none, transparent where nothing is drawn) and a picture file drawn
 * over it, covering the frame (NULL or "": none). The picture is read when the video is made. */
TF_API tf_status tf_video_look_set_background(tf_video_look *look, const tf_rgb *colour, const char *image_path);
/* Announcer: where the face's rotation origin O (the neck) stands in the frame, pixels (origin_xy
 * NULL: centred on the bottom edge), and its eye distance d there (0: the canvas as tall as the frame). */
TF_API tf_status tf_video_look_set_face_placement(tf_video_look *look, const double origin_xy[2], double d_px);
/* How the face's shapes are painted. Errors: TF_ERR_INVALID_ARGUMENT if look is NULL or face_look is
 * not a tf_face_look. */
TF_API tf_status tf_video_look_set_face_look(tf_video_look *look, tf_face_look face_look);
/* Draws the clothes layer (neck and shoulders) if draw_clothes is non-zero (the default), in `colour`
 * (#2f4f7f by default), as tf_frame_options_set_clothes. */
TF_API tf_status tf_video_look_set_clothes(tf_video_look *look, int draw_clothes, tf_rgb colour);
/* The outline width, in units of d (0.025 by default; > 0, checked when the video is made). */
TF_API tf_status tf_video_look_set_stroke_width_in_d(tf_video_look *look, double stroke_width_in_d);

/* Writes a video of `face` playing `animation` with the speech at audio_path (NULL or "": silent):
 * frame k shows the animation at k / fps, as many frames as cover the speech, so the file lasts as
 * long as the speech within a frame. video and look may be NULL (defaults: 1280 x 720, 30 fps, the
 * announcer); progress may be NULL (fraction of frames, stage "video"; non-zero cancels). Written
 * through a temporary file: a failure or a cancel leaves none.
 * Errors: TF_ERR_INVALID_ARGUMENT as tf_check_video_options or for an empty animation; TF_ERR_FILE if
 * the audio, the picture or the output cannot be read or written; TF_ERR_CANCELLED. */
TF_API tf_status tf_render_video(const char *path, const tf_face_model *face, const tf_animation *animation,
                                 const char *audio_path, const tf_video_options *video, const tf_video_look *look,
                                 tf_progress_fn progress, void *user_data);

#ifdef __cplusplus
}
#endif

#endif
