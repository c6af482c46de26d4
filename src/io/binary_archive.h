#pragma once
// The binary encoding of checkpoint files (io/checkpoint.h), for every stage that saves a
// part of one: values as their native bytes, strings and vectors with a u64 count first,
// pairs and Vec2 member by member, any other struct through its describe() (found by
// argument-dependent lookup):
//
//   template <class A, class S>
//   void describe(A& a, S& s) requires std::is_same_v<std::remove_const_t<S>, MyState> {
//     a(s.first_member);
//     a(s.second_member);
//   }
//
// One describe() serves both directions (BinaryWriter with const objects, BinaryReader with
// mutable ones), so that each field is listed once.
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "geometry/vec2.h"

namespace sg {

namespace binary_archive_detail {
template <class T>
struct is_vector : std::false_type {};
template <class T, class A>
struct is_vector<std::vector<T, A>> : std::true_type {};
template <class T>
struct is_pair : std::false_type {};
template <class A, class B>
struct is_pair<std::pair<A, B>> : std::true_type {};
}  // namespace binary_archive_detail

// Appends values as their native bytes; strings and vectors with a u64 count first.
class BinaryWriter {
 public:
  std::string bytes;

  template <class T>
  void operator()(const T& v) {
    using namespace binary_archive_detail;
    if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>) {
      raw(&v, sizeof v);
    } else if constexpr (std::is_same_v<T, std::string>) {
      (*this)(static_cast<std::uint64_t>(v.size()));
      raw(v.data(), v.size());
    } else if constexpr (std::is_same_v<T, Vec2>) {
      (*this)(v.x());
      (*this)(v.y());
    } else if constexpr (is_vector<T>::value) {
      (*this)(static_cast<std::uint64_t>(v.size()));
      if constexpr (std::is_arithmetic_v<typename T::value_type>)
        raw(v.data(), v.size() * sizeof(typename T::value_type));
      else
        for (const auto& e : v)
          (*this)(e);
    } else if constexpr (is_pair<T>::value) {
      (*this)(v.first);
      (*this)(v.second);
    } else {
      describe(*this, v);
    }
  }

 private:
  void raw(const void* p, std::size_t n) { bytes.append(static_cast<const char*>(p), n); }
};

// Thrown by BinaryReader when the bytes end early or hold an impossible count or flag; the
// caller turns it into a message naming the file.
struct MalformedPayload {
  std::string what;
};

class BinaryReader {
 public:
  explicit BinaryReader(std::string_view bytes) : bytes_(bytes) {}
  bool at_end() const { return position_ == bytes_.size(); }
  // The bytes not read yet, consumed: a part of the payload another stage decodes.
  std::string_view take_rest() {
    const std::string_view rest = bytes_.substr(position_);
    position_ = bytes_.size();
    return rest;
  }

  template <class T>
  void operator()(T& v) {
    using namespace binary_archive_detail;
    if constexpr (std::is_same_v<T, bool>) {
      std::uint8_t b = 0;
      raw(&b, 1);
      if (b > 1) throw MalformedPayload{"a flag holds " + std::to_string(b)};
      v = b != 0;
    } else if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>) {
      raw(&v, sizeof v);
    } else if constexpr (std::is_same_v<T, std::string>) {
      v.resize(count(1));
      raw(v.data(), v.size());
    } else if constexpr (std::is_same_v<T, Vec2>) {
      (*this)(v.x());
      (*this)(v.y());
    } else if constexpr (is_vector<T>::value) {
      using E = typename T::value_type;
      v.resize(count(std::is_arithmetic_v<E> ? sizeof(E) : 1));
      if constexpr (std::is_arithmetic_v<E>)
        raw(v.data(), v.size() * sizeof(E));
      else
        for (auto& e : v)
          (*this)(e);
    } else if constexpr (is_pair<T>::value) {
      (*this)(v.first);
      (*this)(v.second);
    } else {
      describe(*this, v);
    }
  }

 private:
  std::string_view bytes_;
  std::size_t position_ = 0;

  void raw(void* p, std::size_t n) {
    if (n > bytes_.size() - position_) throw MalformedPayload{"the payload ends early"};
    if (n == 0) return;  // an empty vector's data() may be null, which memcpy may not take
    std::memcpy(p, bytes_.data() + position_, n);
    position_ += n;
  }
  // A count of elements of at least `element_bytes` each: refused if the rest of the
  // payload cannot hold them (no huge allocation from a damaged count).
  std::size_t count(std::size_t element_bytes) {
    std::uint64_t n = 0;
    raw(&n, sizeof n);
    if (n > (bytes_.size() - position_) / element_bytes)
      throw MalformedPayload{"a count of " + std::to_string(n) + " exceeds the payload"};
    return static_cast<std::size_t>(n);
  }
};

}  // namespace sg
