#pragma once
// POPUP_REFERS_INTO_ARGUMENT marks a function that returns a reference into one of its arguments,
// such as a lookup by name. GCC 14 (Debian 13) takes that reference for a dangling one when the
// call also has a temporary argument (the name as a std::string) and warns -Wdangling-reference;
// GCC's no_dangling attribute tells it otherwise. GCC 12 and clang do not warn.
#if defined(__has_cpp_attribute)
#if __has_cpp_attribute(gnu::no_dangling)
#define POPUP_REFERS_INTO_ARGUMENT [[gnu::no_dangling]]
#endif
#endif
#ifndef POPUP_REFERS_INTO_ARGUMENT
#define POPUP_REFERS_INTO_ARGUMENT
#endif
