// Floating-point std::from_chars and std::to_chars for the browser build: Emscripten 3.1.6's libc++
// (LLVM 14) has only the integer ones, and the scene reader and the command line read floats with
// them. Included before every source of the web build (web.cmake), nowhere else. The same contract
// in the C locale: no leading space or '+', the whole number or nothing, ERANGE as
// result_out_of_range (the value still set, as the scene reader's message wants to tell), and
// to_chars the shortest text that reads back as the same value.
#pragma once
#ifdef __cplusplus
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>

namespace std {
namespace stencil_web {

template <typename T, typename Parse>
from_chars_result fromChars(const char* first, const char* last, T& value, Parse parse) {
  if (first == last || *first == ' ' || *first == '\t' || *first == '\n' || *first == '+' ||
      (last - first > 1 && first[0] == '0' && (first[1] == 'x' || first[1] == 'X')))
    return {first, errc::invalid_argument};
  const string text(first, last);  // strtod reads up to a NUL
  char* end = nullptr;
  errno = 0;
  const T parsed = parse(text.c_str(), &end);
  if (end == text.c_str()) return {first, errc::invalid_argument};
  const char* stop = first + (end - text.c_str());
  if (errno == ERANGE) {
    value = parsed;
    return {stop, errc::result_out_of_range};
  }
  value = parsed;
  return {stop, errc{}};
}

template <typename T, typename Parse>
to_chars_result toChars(char* first, char* last, T value, int maxDigits, Parse parse) {
  char buffer[64];
  int length = 0;
  for (int digits = 1; digits <= maxDigits; ++digits) {
    length = snprintf(buffer, sizeof buffer, "%.*g", digits, static_cast<double>(value));
    if (parse(buffer, nullptr) == value) break;
  }
  if (length < 0 || length > last - first) return {last, errc::value_too_large};
  memcpy(first, buffer, static_cast<size_t>(length));
  return {first + length, errc{}};
}

}  // namespace stencil_web

inline from_chars_result from_chars(const char* first, const char* last, float& value) {
  return stencil_web::fromChars(first, last, value, [](const char* s, char** e) { return strtof(s, e); });
}
inline from_chars_result from_chars(const char* first, const char* last, double& value) {
  return stencil_web::fromChars(first, last, value, [](const char* s, char** e) { return strtod(s, e); });
}
inline to_chars_result to_chars(char* first, char* last, float value) {
  return stencil_web::toChars(first, last, value, 9, [](const char* s, char** e) { return strtof(s, e); });
}
inline to_chars_result to_chars(char* first, char* last, double value) {
  return stencil_web::toChars(first, last, value, 17, [](const char* s, char** e) { return strtod(s, e); });
}

}  // namespace std
#endif
