/* The C tests' shared harness: counters, CHECK and CHECK_CLOSE, and the summary
 * line ctest logs show. Included by every tests/test_*.c; one translation unit
 * per test, so the counters can be file-static here. Not a test itself: its name
 * stays out of the test_*.c glob in tests/CMakeLists.txt. */
#ifndef TIPPE_TESTS_CHECK_H
#define TIPPE_TESTS_CHECK_H

#include <math.h>
#include <stdio.h>

static int check_passed, check_failed;

/* Prints where and what failed; the caller's message follows on the same line. */
static inline void check_fail_at(const char *file, int line, const char *what)
{
    check_failed++;
    printf("FAIL %s:%d: %s: ", file, line, what);
}

/* CHECK(cond, fmt, ...): the message is formatted only when cond fails, so it
 * may name values that are meaningless (or costly) when the check passes. A
 * macro rather than a function so that printf checks fmt against its arguments. */
#define CHECK(cond, ...)                                                                          \
    do {                                                                                          \
        if (cond) {                                                                               \
            check_passed++;                                                                       \
        } else {                                                                                  \
            check_fail_at(__FILE__, __LINE__, #cond);                                             \
            printf(__VA_ARGS__);                                                                  \
            printf("\n");                                                                         \
        }                                                                                         \
    } while (0)

/* CHECK_CLOSE(got, want, rel, fmt, ...): |got - want| <= rel |want|, each
 * argument evaluated once. On failure both values and the relative error are
 * printed (17 digits, enough to tell any two doubles apart) before the message. */
#define CHECK_CLOSE(got, want, rel, ...)                                                          \
    do {                                                                                          \
        double check_got_ = (got), check_want_ = (want), check_rel_ = (rel);                      \
        if (fabs(check_got_ - check_want_) <= check_rel_ * fabs(check_want_)) {                   \
            check_passed++;                                                                       \
        } else {                                                                                  \
            check_fail_at(__FILE__, __LINE__, #got " ~ " #want " within " #rel);                  \
            printf("got %.17g, want %.17g, rel err %.3g: ", check_got_, check_want_,              \
                   fabs(check_got_ - check_want_) / fabs(check_want_));                           \
            printf(__VA_ARGS__);                                                                  \
            printf("\n");                                                                         \
        }                                                                                         \
    } while (0)

/* Prints "NAME: N passed, M failed" and gives main's exit status (0 when
 * nothing failed): end main with return check_summary("test_x"). */
static inline int check_summary(const char *name)
{
    printf("%s: %d passed, %d failed\n", name, check_passed, check_failed);
    return check_failed != 0;
}

#endif
