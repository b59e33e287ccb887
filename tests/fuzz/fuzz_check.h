// What the fuzz targets require of every message they get: one line of printable ASCII that
// starts with the input's name. Anything else stops the run (__builtin_trap), as a crash would.
#pragma once
#include <string_view>

namespace stencil::fuzz {

inline void checkMessage(std::string_view message, std::string_view name) {
  if (!message.starts_with(name)) __builtin_trap();
  for (const char c : message)
    if (c < 0x20 || c > 0x7e) __builtin_trap();
}

}  // namespace stencil::fuzz
