// libFuzzer target: the checkpoint reader (read_checkpoint, a pure function of the bytes) and
// every field it accepts, read back by its type. An InputError is a correct answer to any
// input; a crash, a sanitizer report or any other exception is a finding.
//
// Mutated bytes almost never keep the checksum, so the fuzzer would rarely get past it to the
// header and the fields: the target writes the FNV-1a-64 of the input's other bytes into its
// last 8 first (the checksum test itself is one comparison; ctest's [checkpoint] cases show a
// damaged byte is refused).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "ycore/output/checkpoint_file.h"
#include "ycore/input/input_error.h"

namespace {

template <class T>
void read_back(const ydry::Checkpoint& c, const std::string& name) {
  std::vector<T> values;
  c.take(name, values);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string bytes(reinterpret_cast<const char*>(data), size);
  if (bytes.size() >= 8) {
    const std::uint64_t checksum = ydry::fnv1a64(bytes.data(), bytes.size() - 8);
    std::memcpy(&bytes[bytes.size() - 8], &checksum, 8);
  }
  try {
    const ydry::Checkpoint c = ydry::read_checkpoint(std::move(bytes));
    for (const auto& [name, field] : c.fields) switch (field.type) {
        case ydry::FieldType::f64: read_back<double>(c, name); break;
        case ydry::FieldType::u64: read_back<std::uint64_t>(c, name); break;
        case ydry::FieldType::u32: read_back<std::uint32_t>(c, name); break;
        case ydry::FieldType::u8: read_back<std::uint8_t>(c, name); break;
      }
  } catch (const ydry::InputError&) {
  }
  return 0;
}
