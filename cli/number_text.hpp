// Fast, exact number formatting for text outputs: std::to_chars writes the
// shortest string that reads back to the same double, without iostream costs.
#pragma once

#include <charconv>
#include <string>

namespace cadmedial {

inline void appendNumber(std::string& out, double value) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, result.ptr);
}

template <typename Int>
inline void appendInteger(std::string& out, Int value) {
  char buf[24];
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, result.ptr);
}

}  // namespace cadmedial
