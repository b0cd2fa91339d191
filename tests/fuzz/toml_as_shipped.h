// Included before anything else in the fuzz targets (tests/fuzz/CMakeLists.txt), which compile
// toml++ 3.3 (Debian 12) header-only, instrumented, with its assertions on, rather than link
// Debian's uninstrumented library. Two things of that library as built (GCC 12, -DNDEBUG) are
// kept, so that the fuzzer judges the parser ydry ships; each is a regression test of ydry
// against the shipped library in tests/test_fuzz_findings.cpp.
//
// 1. toml++'s preconditions written TOML_ASSERT_ASSUME compile to nothing there (GCC 12 has no
//    __builtin_assume), and toml++ 3.3 breaks some itself: it calls parse_key on a table
//    header that starts with a character no key starts with ("[!]", "[\0"; fixed in toml++
//    after 3.3) and parse_value on a '}' in an array ("[}"). The
//    code after each precondition reports the input as a parse error ("expected bare key
//    starting character or string delimiter", "could not determine value type"), which ydry
//    turns into an InputError. So here too they are not checked; toml++'s plain assertions
//    are, and ASan and UBSan watch the code that follows.
// 2. is_non_ascii_horizontal_whitespace reaches TOML_UNREACHABLE for most non-ASCII code
//    points where whitespace may come ("end_time = 100.0 °"; fixed in toml++ after 3.3).
//    Debian's build answers "not whitespace" and toml++ reports "expected a
//    comment or whitespace, saw '°'": toml_ubsan_ignore.txt exempts that one function from
//    UBSan.
#pragma once

#include <toml++/impl/preprocessor.h>

#undef TOML_ASSERT_ASSUME
#define TOML_ASSERT_ASSUME(expression) static_cast<void>(0)
