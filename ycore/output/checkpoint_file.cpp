#include "ycore/output/checkpoint_file.h"

#include <cstring>

namespace ydry {
namespace {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the checkpoint format is little-endian");

constexpr char kMagic[8] = {'Y', 'D', 'R', 'Y', 'C', 'K', 'P', 'T'};
constexpr std::size_t kMaxName = 256;  // also the longest version string

std::size_t type_size(FieldType type) {
  switch (type) {
    case FieldType::f64: case FieldType::u64: return 8;
    case FieldType::u32: return 4;
    case FieldType::u8: return 1;
  }
  return 0;  // not a type
}

const char* type_name(FieldType type) {
  switch (type) {
    case FieldType::f64: return "f64";
    case FieldType::u64: return "u64";
    case FieldType::u32: return "u32";
    case FieldType::u8: return "u8";
  }
  return "unknown";
}

template <class T>
void append(std::string& out, T v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

// Reads through bytes [position, end), every read checked against what is left.
struct Cursor {
  const std::string& bytes;
  std::size_t position, end;
  std::size_t left() const { return end - position; }
  void need(std::size_t size, const std::string& what) const {
    if (size > left())
      throw InputError("truncated checkpoint: " + what + " needs " + std::to_string(size) + " bytes at offset " +
                       std::to_string(position) + ", " + std::to_string(left()) + " are left");
  }
  template <class T>
  T number(const std::string& what) {
    need(sizeof(T), what);
    T v;
    std::memcpy(&v, bytes.data() + position, sizeof v);
    position += sizeof v;
    return v;
  }
  std::string text(std::size_t size, const std::string& what) {
    need(size, what);
    position += size;
    return bytes.substr(position - size, size);
  }
  // A u32 length (1 to kMaxName, or 0 to kMaxName when `empty_ok`) and that many bytes.
  std::string short_text(const std::string& what, bool empty_ok) {
    const std::uint32_t size = number<std::uint32_t>(what + " length");
    if (size > kMaxName || (size == 0 && !empty_ok))
      throw InputError("damaged checkpoint: " + what + " length " + std::to_string(size) + " at offset " +
                       std::to_string(position - 4) + " (1 to " + std::to_string(kMaxName) + ")");
    return text(size, what);
  }
};

}  // namespace

std::uint64_t fnv1a64(const char* bytes, std::size_t size, std::uint64_t hash) {
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= static_cast<unsigned char>(bytes[i]);
    hash *= 0x100000001b3ull;
  }
  return hash;
}

void CheckpointWriter::put(const std::string& name, FieldType type, const void* data, std::size_t count,
                           std::size_t size) {
  append(payload, std::uint32_t(name.size()));
  payload += name;
  append(payload, type);
  append(payload, std::uint64_t(count));
  payload.append(static_cast<const char*>(data), count * size);
}

std::string checkpoint_file_bytes(const std::string& ydry_version, std::uint64_t deck_hash,
                                  const std::string& payload) {
  std::string out(kMagic, sizeof kMagic);
  append(out, kCheckpointFormat);
  append(out, std::uint32_t(ydry_version.size()));
  out += ydry_version;
  append(out, deck_hash);
  append(out, std::uint64_t(payload.size()));
  out += payload;
  append(out, fnv1a64(out));
  return out;
}

void Checkpoint::take(const std::string& name, std::string& out) const {
  const Field& f = field(name, FieldType::u8, 0);
  out = bytes.substr(f.offset, f.count);
}

void Checkpoint::take(const std::string& name, bool& out) const {
  std::uint8_t v = 0;
  take(name, v);
  out = v != 0;
}

const Checkpoint::Field& Checkpoint::field(const std::string& name, FieldType type, std::size_t count) const {
  const auto found = fields.find(name);
  if (found == fields.end()) throw InputError(source + ": has no field '" + name + "'");
  const Field& f = found->second;
  if (f.type != type)
    throw InputError(source + ": field '" + name + "' holds " + type_name(f.type) + ", not " + type_name(type));
  if (count > 0 && f.count != count)
    throw InputError(source + ": field '" + name + "' holds " + std::to_string(f.count) + " values, not " +
                     std::to_string(count));
  return f;
}

Checkpoint read_checkpoint(std::string bytes) {
  Checkpoint c;
  c.bytes = std::move(bytes);
  const std::string& b = c.bytes;
  if (b.size() < sizeof kMagic || std::memcmp(b.data(), kMagic, sizeof kMagic) != 0)
    throw InputError("not a ydry checkpoint (it does not start with YDRYCKPT)");
  if (b.size() < sizeof kMagic + 8) throw InputError("truncated checkpoint: " + std::to_string(b.size()) + " bytes");
  Cursor header{b, sizeof kMagic, b.size() - 8};  // the last 8 bytes: the checksum
  const std::uint32_t format = header.number<std::uint32_t>("the format version");
  if (format != kCheckpointFormat)
    throw InputError("checkpoint format version " + std::to_string(format) + "; this ydry reads version " +
                     std::to_string(kCheckpointFormat));
  c.ydry_version = header.short_text("the ydry version", true);
  c.deck_hash = header.number<std::uint64_t>("the deck hash");
  const std::uint64_t payload = header.number<std::uint64_t>("the payload length");
  if (payload != header.left())
    throw InputError("truncated or extended checkpoint: its header gives a payload of " + std::to_string(payload) +
                     " bytes, the file holds " + std::to_string(header.left()));
  std::uint64_t stored = 0;
  std::memcpy(&stored, b.data() + b.size() - 8, 8);
  if (stored != fnv1a64(b.data(), b.size() - 8))
    throw InputError("damaged checkpoint: the checksum does not match its contents");

  while (header.left() > 0) {
    const std::string name = header.short_text("a field name", false);
    const FieldType type = FieldType(header.number<std::uint8_t>("the type of field '" + name + "'"));
    const std::size_t size = type_size(type);
    if (size == 0) throw InputError("damaged checkpoint: field '" + name + "' has an unknown type");
    const std::uint64_t count = header.number<std::uint64_t>("the length of field '" + name + "'");
    if (count > header.left() / size)
      throw InputError("damaged checkpoint: field '" + name + "' claims " + std::to_string(count) + " values of " +
                       std::to_string(size) + " bytes, " + std::to_string(header.left()) + " bytes are left");
    if (!c.fields.emplace(name, Checkpoint::Field{type, header.position, std::size_t(count)}).second)
      throw InputError("damaged checkpoint: field '" + name + "' appears twice");
    header.position += std::size_t(count) * size;
  }
  return c;
}

}  // namespace ydry
