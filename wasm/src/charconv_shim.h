// Emscripten 3.1.6 ships libc++ 14, which has no floating-point std::from_chars (the call resolves to a deleted
// overload). rtl/io/CarmenLog.h parses doubles with it, so the wasm build supplies the overload, on strtod, with
// from_chars' rules for the accepted text (no leading whitespace or '+', no hex prefix). Native builds use the
// standard library's own; nothing here is compiled there. Include before <rtl/io/CarmenLog.h>.
#pragma once

#include <charconv>

#if defined(__EMSCRIPTEN__) && defined(_LIBCPP_VERSION) && _LIBCPP_VERSION < 170000
#include <cerrno>
#include <cstdlib>
#include <string>
#include <system_error>

namespace std {
inline from_chars_result from_chars(const char* first, const char* last, double& value,
                                    chars_format = chars_format::general) {
  from_chars_result r{first, errc::invalid_argument};
  if (first == last || *first == '+' || *first == ' ' || *first == '\t') return r;
  const char* digits = *first == '-' ? first + 1 : first;
  if (last - digits >= 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
    r.ptr = digits + 1;  // from_chars reads the "0" and stops at the 'x'
    r.ec = errc();
    value = first == digits ? 0.0 : -0.0;
    return r;
  }
  const std::string text(first, last);
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str()) return r;
  r.ptr = first + (end - text.c_str());
  if (errno == ERANGE && (v == HUGE_VAL || v == -HUGE_VAL)) {
    r.ec = errc::result_out_of_range;
    return r;
  }
  r.ec = errc();
  value = v;
  return r;
}
}  // namespace std
#endif
