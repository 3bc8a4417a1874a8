/* talkface.h and talkface_photo.h must compile as strict C99 on their own, and twice (their include
 * guards work). Compiled, never linked or run: a warning here fails the build (-std=c99 -pedantic
 * -Werror). */
#include "talkface/talkface_photo.h"
#include "talkface/talkface_photo.h"
#include "talkface/talkface.h"
#include "talkface/talkface.h"

int header_is_c99(void);

int header_is_c99(void) {
    tf_face_model *face = NULL;
    tf_rgb colour = {0, 0, 0};
    tf_mouth_shape shape = TF_MOUTH_A;
    tf_side side = TF_SIDE_LEFT;
    tf_photo_locator locator = TF_PHOTO_LOCATOR_THESIS;
    (void)locator;
    return face == NULL && colour.r == 0 && shape == TF_MOUTH_A && side == TF_SIDE_LEFT ? TF_OK : 1;
}
