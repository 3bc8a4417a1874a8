/* The checks of the C ABI tests. Each test function keeps an `int failures` that CHECK counts into;
 * main exits non-zero if any check failed. */
#ifndef TALKFACE_TESTS_C_CHECK_H
#define TALKFACE_TESTS_C_CHECK_H

#include <stdio.h>
#include <string.h>

#include "talkface/talkface.h"

/* Counts into the enclosing function's `failures`; prints where and this thread's last error. */
#define CHECK(condition)                                                                            \
    do {                                                                                            \
        if (!(condition)) {                                                                         \
            ++failures;                                                                             \
            fprintf(stderr, "%s:%d: CHECK(%s) failed; tf_last_error_message: \"%s\"\n", __FILE__,   \
                    __LINE__, #condition, tf_last_error_message());                                 \
        }                                                                                           \
    } while (0)

#define CHECK_OK(call) CHECK((call) == TF_OK)

/* status == expected and the message contains `needle`. */
#define CHECK_FAILS_WITH(call, expected, needle)                                                    \
    do {                                                                                            \
        tf_status status_ = (call);                                                                 \
        CHECK(status_ == (expected));                                                               \
        CHECK(strstr(tf_last_error_message(), (needle)) != NULL);                                   \
    } while (0)

#endif
