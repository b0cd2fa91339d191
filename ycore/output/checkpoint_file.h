// The byte format of a checkpoint (ycore/output/checkpoint.h says what one holds): a header, a
// payload of named, typed arrays, and a checksum of everything before it.
//
//   "YDRYCKPT"                      8 bytes, the magic
//   format version                  u32 (kCheckpointFormat)
//   ydry version                    u32 length (at most 256), then its bytes
//   deck hash                       u64, FNV-1a-64 of the resolved deck's values
//   payload length                  u64
//   payload                         fields, each: u32 name length (1 to 256), the name,
//                                   u8 type, u64 element count, the elements
//   checksum                        u64, FNV-1a-64 of every byte before it
//
// Numbers are little-endian (ydry builds only on little-endian hosts). read_checkpoint takes
// any bytes: whatever is wrong with them (another file, a truncated or altered one, a newer
// format) is an InputError that says what, and no length it reads is trusted beyond the bytes
// that are there, so it allocates no more than the input's size.
#pragma once

#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include "ycore/input/input_error.h"

namespace ydry {

constexpr std::uint32_t kCheckpointFormat = 1;

// FNV-1a, 64 bits, of `bytes`, continuing from `hash`.
std::uint64_t fnv1a64(const char* bytes, std::size_t size, std::uint64_t hash = 0xcbf29ce484222325ull);
inline std::uint64_t fnv1a64(const std::string& bytes) { return fnv1a64(bytes.data(), bytes.size()); }
// Adds the bytes of an array's elements to `hash`.
template <class T>
void hash_array(std::uint64_t& hash, const std::vector<T>& v) {
  hash = fnv1a64(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T), hash);
}

// Element types of a field.
enum class FieldType : std::uint8_t { f64 = 1, u64 = 2, u32 = 3, u8 = 4 };

template <class T>
constexpr FieldType field_type() {
  static_assert(std::is_same_v<T, double> || std::is_same_v<T, std::uint64_t> ||
                std::is_same_v<T, std::uint32_t> || std::is_same_v<T, std::uint8_t>);
  if constexpr (std::is_same_v<T, double>) return FieldType::f64;
  if constexpr (std::is_same_v<T, std::uint64_t>) return FieldType::u64;
  if constexpr (std::is_same_v<T, std::uint32_t>) return FieldType::u32;
  return FieldType::u8;  // also text
}

// The payload, built field by field.
struct CheckpointWriter {
  std::string payload;
  void put(const std::string& name, FieldType type, const void* data, std::size_t count, std::size_t size);
  template <class T>
  void put(const std::string& name, const std::vector<T>& v) { put(name, field_type<T>(), v.data(), v.size(), sizeof(T)); }
  void put(const std::string& name, const std::string& text) { put(name, FieldType::u8, text.data(), text.size(), 1); }
  void put(const std::string& name, double v) { put(name, FieldType::f64, &v, 1, sizeof v); }
  void put(const std::string& name, std::uint64_t v) { put(name, FieldType::u64, &v, 1, sizeof v); }
  void put(const std::string& name, bool v) { put(name, std::uint8_t(v)); }
  void put(const std::string& name, std::uint8_t v) { put(name, FieldType::u8, &v, 1, 1); }
};

// The whole file: header, payload and checksum.
std::string checkpoint_file_bytes(const std::string& ydry_version, std::uint64_t deck_hash,
                                  const std::string& payload);

// A checkpoint read back: its header, and its fields by name (offsets into `bytes`).
struct Checkpoint {
  struct Field {
    FieldType type;
    std::size_t offset, count;
  };
  std::string bytes;
  std::string source = "checkpoint";  // its file, for messages
  std::string ydry_version;
  std::uint64_t deck_hash = 0;
  std::map<std::string, Field> fields;

  // Field `name` into `out` (any length; a scalar takes a field of one element, a string one
  // of bytes). InputError when it is missing or of another type.
  template <class T>
  void take(const std::string& name, std::vector<T>& out) const {
    const Field& f = field(name, field_type<T>(), 0);
    out.resize(f.count);
    if (f.count) std::copy_n(bytes.data() + f.offset, f.count * sizeof(T), reinterpret_cast<char*>(out.data()));
  }
  void take(const std::string& name, std::string& out) const;
  template <class T>
  void take(const std::string& name, T& out) const {
    const Field& f = field(name, field_type<T>(), 1);
    std::copy_n(bytes.data() + f.offset, sizeof(T), reinterpret_cast<char*>(&out));
  }
  void take(const std::string& name, bool& out) const;
  // The field, checked for its type and, when count > 0, its element count.
  const Field& field(const std::string& name, FieldType type, std::size_t count) const;
};

// Parses and checks a checkpoint file's bytes (see the top of this file). Throws InputError.
// A pure function of the bytes: the entry point of the checkpoint fuzz target.
Checkpoint read_checkpoint(std::string bytes);

}  // namespace ydry
