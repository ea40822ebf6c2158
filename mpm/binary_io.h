// Raw binary reading and writing of checkpoint data: fixed-size values, arrays and text, each
// array and text preceded by its length. Reads throw std::runtime_error on a short or
// implausible stream.
#pragma once

#include <cstdint>
#include <cstring>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace vulnus::mpm::binary
{
template <class T>
void put(std::ostream& out, const T& value)
{
  static_assert(std::is_standard_layout_v<T>); // fixed-size Eigen types and PODs
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <class T>
void put_vector(std::ostream& out, const std::vector<T>& values)
{
  static_assert(std::is_standard_layout_v<T>);
  put(out, static_cast<std::uint64_t>(values.size()));
  out.write(reinterpret_cast<const char*>(values.data()),
            static_cast<std::streamsize>(sizeof(T) * values.size()));
}

inline void put_text(std::ostream& out, const std::string& text)
{
  put(out, static_cast<std::uint64_t>(text.size()));
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

template <class T>
void get(std::istream& in, T& value)
{
  in.read(reinterpret_cast<char*>(&value), sizeof(T));
  if (!in)
    throw std::runtime_error("checkpoint is truncated");
}

/// The length prefix of an array or text, refused above `limit` (a corrupt file).
inline std::uint64_t get_length(std::istream& in, const std::uint64_t limit)
{
  std::uint64_t n = 0;
  get(in, n);
  if (n > limit)
    throw std::runtime_error("checkpoint is corrupt (array length " + std::to_string(n) + ")");
  return n;
}

template <class T>
void get_vector(std::istream& in, std::vector<T>& values)
{
  values.resize(get_length(in, std::uint64_t(1) << 34));
  in.read(reinterpret_cast<char*>(values.data()),
          static_cast<std::streamsize>(sizeof(T) * values.size()));
  if (!in)
    throw std::runtime_error("checkpoint is truncated");
}

inline void get_text(std::istream& in, std::string& text)
{
  text.assign(get_length(in, std::uint64_t(1) << 30), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (!in)
    throw std::runtime_error("checkpoint is truncated");
}
/// Reads an 8-byte tag; throws `what` when it is missing or different.
inline void expect_tag(std::istream& in, const char (&tag)[8], const char* what)
{
  char read[8] = {};
  in.read(read, sizeof(read));
  if (!in || std::memcmp(read, tag, sizeof(read)) != 0)
    throw std::runtime_error(what);
}
} // namespace vulnus::mpm::binary
