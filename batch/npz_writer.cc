// The streaming NPZ writer (batch/npz_writer.h). ZIP layout from PKWARE's
// APPNOTE (local headers, central directory, end record, ZIP64 extra field
// 0x0001 and the ZIP64 end record and locator); NPY layout from numpy's
// format docs (magic, version 1.0, little-endian header length, header dict).

#include "batch/npz_writer.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <bit>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace manyworlds::npz {
namespace {

// Frames are appended as the host holds them; NPY's descrs here say '<'.
static_assert(std::endian::native == std::endian::little, "NPZ writer: little-endian hosts only");

constexpr std::uint64_t k32BitLimit = 0xFFFFFFFFu;
constexpr std::size_t kBufferBytes = std::size_t(1) << 20;  // per growing array
constexpr std::uint16_t kDosDate1980 = (1 << 5) | 1;         // 1980-01-01: reproducible files

[[noreturn]] void ThrowErrno(const std::string& what, const std::string& path) {
  throw std::runtime_error(what + " '" + path + "': " + std::strerror(errno));
}

void WriteAll(int fd, const void* data, std::size_t size, const std::string& path) {
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t written = ::write(fd, bytes, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      ThrowErrno("cannot write", path);
    }
    bytes += written;
    size -= std::size_t(written);
  }
}

void PWriteAll(int fd, const void* data, std::size_t size, std::uint64_t offset,
               const std::string& path) {
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t written = ::pwrite(fd, bytes, size, off_t(offset));
    if (written < 0) {
      if (errno == EINTR) continue;
      ThrowErrno("cannot write", path);
    }
    bytes += written;
    size -= std::size_t(written);
    offset += std::uint64_t(written);
  }
}

// Little-endian fields of ZIP records, appended to a byte string.
struct LittleEndian {
  std::string bytes;
  LittleEndian& U16(std::uint64_t v) { return Put(v, 2); }
  LittleEndian& U32(std::uint64_t v) { return Put(v, 4); }
  LittleEndian& U64(std::uint64_t v) { return Put(v, 8); }
  LittleEndian& Text(const std::string& s) {
    bytes += s;
    return *this;
  }
  LittleEndian& Put(std::uint64_t v, int size) {
    for (int i = 0; i < size; ++i) bytes.push_back(char((v >> (8 * i)) & 0xFF));
    return *this;
  }
};

const std::array<std::uint32_t, 256>& CrcTable() {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  return table;
}

std::uint64_t Product(const std::vector<std::uint64_t>& shape) {
  std::uint64_t n = 1;
  for (const std::uint64_t d : shape) n *= d;
  return n;
}

std::string ItemBytesOfDescr(const std::string& descr, std::size_t item_bytes) {
  return descr + " (" + std::to_string(item_bytes) + " bytes)";
}

}  // namespace

std::string NpyHeader(const std::string& descr, std::span<const std::uint64_t> shape) {
  std::string dict = "{'descr': '" + descr + "', 'fortran_order': False, 'shape': (";
  for (std::size_t i = 0; i < shape.size(); ++i) {
    dict += std::to_string(shape[i]);
    if (i + 1 < shape.size() || shape.size() == 1) dict += ",";
    if (i + 1 < shape.size()) dict += " ";
  }
  dict += "), }";
  // magic (6) + version (2) + length (2) + dict + spaces + '\n': a multiple of 64.
  const std::size_t unpadded = 10 + dict.size() + 1;
  dict.append((64 - unpadded % 64) % 64, ' ');
  dict += '\n';
  std::string header("\x93NUMPY\x01\x00", 8);
  header += LittleEndian().U16(dict.size()).bytes;
  return header + dict;
}

std::vector<std::uint32_t> Utf32(const std::string& utf8) {
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < utf8.size();) {
    const unsigned char lead = static_cast<unsigned char>(utf8[i]);
    const int length = lead < 0x80 ? 1 : (lead >> 5) == 6 ? 2 : (lead >> 4) == 14 ? 3
                                   : (lead >> 3) == 30 ? 4 : 0;
    if (length == 0 || i + std::size_t(length) > utf8.size()) {
      throw std::invalid_argument("not UTF-8: '" + utf8 + "'");
    }
    std::uint32_t code = length == 1 ? lead : lead & (0x7Fu >> length);
    for (int k = 1; k < length; ++k) {
      const unsigned char next = static_cast<unsigned char>(utf8[i + std::size_t(k)]);
      if ((next >> 6) != 2) throw std::invalid_argument("not UTF-8: '" + utf8 + "'");
      code = (code << 6) | (next & 0x3Fu);
    }
    out.push_back(code);
    i += std::size_t(length);
  }
  return out;
}

std::uint32_t Crc32(std::span<const std::byte> bytes, std::uint32_t crc) {
  const auto& table = CrcTable();
  crc = ~crc;
  for (const std::byte b : bytes) crc = table[(crc ^ std::uint32_t(b)) & 0xFFu] ^ (crc >> 8);
  return ~crc;
}

struct StreamingNpzWriter::State {
  struct Member {
    std::string name;
    std::string descr;
    std::size_t item_bytes = 0;
    std::vector<std::uint64_t> shape;  // growing: the frame's shape
    bool growing = false;
    std::vector<std::byte> data;  // whole array, or a growing array's unflushed frames
    int fd = -1;                  // growing: unlinked temporary file
    std::uint64_t frames = 0;
    std::uint64_t flushed_bytes = 0;
  };

  std::string path;
  std::string temp_path;
  bool overwrite = false;
  Zip64 zip64 = Zip64::kWhenNeeded;
  int zip_fd = -1;
  bool closed = false;
  std::vector<Member> members;

  void Flush(Member& m) {
    WriteAll(m.fd, m.data.data(), m.data.size(), temp_path);
    m.flushed_bytes += m.data.size();
    m.data.clear();
  }

  // Closes every descriptor and removes the temporary ZIP; never throws.
  void Discard() {
    for (Member& m : members) {
      if (m.fd >= 0) ::close(m.fd);
      m.fd = -1;
    }
    if (zip_fd >= 0) {
      ::close(zip_fd);
      zip_fd = -1;
      ::unlink(temp_path.c_str());
    }
    closed = true;
  }

  void WriteZip();
  // Copies member `m` (NPY header, then data) to the ZIP at `offset`,
  // returning its CRC-32 and size.
  std::pair<std::uint32_t, std::uint64_t> WriteMemberData(Member& m);
};

void StreamingNpzWriter::State::WriteZip() {
  struct Entry {
    std::string name;
    std::uint32_t crc;
    std::uint64_t size, offset;
  };
  std::vector<Entry> entries;
  std::uint64_t position = 0;
  for (Member& m : members) {
    const std::string name = m.name + ".npy";
    std::vector<std::uint64_t> shape = m.shape;
    if (m.growing) shape.insert(shape.begin(), m.frames);
    const std::uint64_t size =
        NpyHeader(m.descr, shape).size() + Product(shape) * std::uint64_t(m.item_bytes);
    const bool big = zip64 == Zip64::kAlways || size >= k32BitLimit;
    LittleEndian local;
    local.U32(0x04034b50).U16(big ? 45 : 20).U16(0).U16(0).U16(0).U16(kDosDate1980);
    local.U32(0);  // CRC-32, patched below
    local.U32(big ? k32BitLimit : size).U32(big ? k32BitLimit : size);
    local.U16(name.size()).U16(big ? 20 : 0).Text(name);
    if (big) local.U16(1).U16(16).U64(size).U64(size);
    WriteAll(zip_fd, local.bytes.data(), local.bytes.size(), temp_path);
    const auto [crc, written] = WriteMemberData(m);
    if (written != size) throw std::logic_error("npz: member size changed while writing");
    const std::uint8_t crc_bytes[4] = {std::uint8_t(crc), std::uint8_t(crc >> 8),
                                       std::uint8_t(crc >> 16), std::uint8_t(crc >> 24)};
    PWriteAll(zip_fd, crc_bytes, 4, position + 14, temp_path);
    entries.push_back({name, crc, size, position});
    position += local.bytes.size() + size;
  }

  const std::uint64_t directory_offset = position;
  LittleEndian directory;
  for (const Entry& e : entries) {
    const bool big =
        zip64 == Zip64::kAlways || e.size >= k32BitLimit || e.offset >= k32BitLimit;
    directory.U32(0x02014b50).U16(big ? 45 : 20).U16(big ? 45 : 20).U16(0).U16(0);
    directory.U16(0).U16(kDosDate1980).U32(e.crc);
    directory.U32(big ? k32BitLimit : e.size).U32(big ? k32BitLimit : e.size);
    directory.U16(e.name.size()).U16(big ? 28 : 0).U16(0).U16(0).U16(0).U32(0);
    directory.U32(big ? k32BitLimit : e.offset).Text(e.name);
    // In APPNOTE's order: uncompressed, compressed size, local header offset.
    if (big) directory.U16(1).U16(24).U64(e.size).U64(e.size).U64(e.offset);
  }
  const std::uint64_t directory_size = directory.bytes.size();
  const bool big_end = zip64 == Zip64::kAlways || entries.size() >= 0xFFFF ||
                       directory_offset >= k32BitLimit || directory_size >= k32BitLimit;
  if (big_end) {
    const std::uint64_t record_offset = directory_offset + directory_size;
    directory.U32(0x06064b50).U64(44).U16(45).U16(45).U32(0).U32(0);
    directory.U64(entries.size()).U64(entries.size()).U64(directory_size).U64(directory_offset);
    directory.U32(0x07064b50).U32(0).U64(record_offset).U32(1);
  }
  directory.U32(0x06054b50).U16(0).U16(0);
  directory.U16(big_end ? 0xFFFF : entries.size()).U16(big_end ? 0xFFFF : entries.size());
  directory.U32(big_end ? k32BitLimit : directory_size);
  directory.U32(big_end ? k32BitLimit : directory_offset).U16(0);
  WriteAll(zip_fd, directory.bytes.data(), directory.bytes.size(), temp_path);
}

std::pair<std::uint32_t, std::uint64_t> StreamingNpzWriter::State::WriteMemberData(Member& m) {
  std::vector<std::uint64_t> shape = m.shape;
  if (m.growing) shape.insert(shape.begin(), m.frames);
  const std::string header = NpyHeader(m.descr, shape);
  WriteAll(zip_fd, header.data(), header.size(), temp_path);
  std::uint32_t crc = Crc32(std::as_bytes(std::span(header)));
  std::uint64_t size = header.size();
  const auto copy = [&](std::span<const std::byte> bytes) {
    WriteAll(zip_fd, bytes.data(), bytes.size(), temp_path);
    crc = Crc32(bytes, crc);
    size += bytes.size();
  };
  if (m.growing) {
    std::vector<std::byte> buffer(kBufferBytes);
    for (std::uint64_t done = 0; done < m.flushed_bytes;) {
      const ssize_t got = ::pread(m.fd, buffer.data(), buffer.size(), off_t(done));
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) ThrowErrno("cannot read back the frames of", temp_path);
      copy(std::span(buffer.data(), std::size_t(got)));
      done += std::uint64_t(got);
    }
  }
  copy(m.data);
  return {crc, size};
}

StreamingNpzWriter::StreamingNpzWriter(std::string path, bool overwrite, Zip64 zip64)
    : state_(std::make_unique<State>()) {
  state_->path = std::move(path);
  state_->overwrite = overwrite;
  state_->zip64 = zip64;
  const std::string& target = state_->path;
  if (target.empty()) throw std::runtime_error("no file name given for the NPZ file");
  struct stat info {};
  if (::stat(target.c_str(), &info) == 0) {
    if (S_ISDIR(info.st_mode)) throw std::runtime_error("'" + target + "' is a folder");
    if (!overwrite) {
      throw std::runtime_error("'" + target + "' exists (not overwritten)");
    }
  }
  std::string name = target + ".partial-XXXXXX";
  const int fd = ::mkstemp(name.data());
  if (fd < 0) ThrowErrno("cannot create a file next to", target);
  state_->temp_path = name;
  state_->zip_fd = fd;
  ::fchmod(fd, 0644);  // mkstemp's 0600 would make the recording private
}

StreamingNpzWriter::~StreamingNpzWriter() {
  if (state_ && !state_->closed) state_->Discard();
}

void StreamingNpzWriter::AddArray(const std::string& name, const std::string& descr,
                                  std::vector<std::uint64_t> shape,
                                  std::span<const std::byte> data) {
  if (state_->closed) throw std::logic_error("npz: AddArray after Close");
  State::Member m;
  m.name = name;
  m.descr = descr;
  m.data.assign(data.begin(), data.end());
  const std::uint64_t items = Product(shape);
  m.item_bytes = items == 0 ? 1 : std::size_t(data.size() / items);
  if (items == 0 ? !data.empty() : data.size() % items != 0) {
    throw std::logic_error("npz: array '" + name + "' has " + std::to_string(data.size()) +
                           " bytes for " + std::to_string(items) + " items");
  }
  m.shape = std::move(shape);
  state_->members.push_back(std::move(m));
}

std::size_t StreamingNpzWriter::AddGrowingArray(const std::string& name, const std::string& descr,
                                                std::size_t item_bytes,
                                                std::vector<std::uint64_t> frame_shape) {
  if (state_->closed) throw std::logic_error("npz: AddGrowingArray after Close");
  State::Member m;
  m.name = name;
  m.descr = descr;
  m.item_bytes = item_bytes;
  m.shape = std::move(frame_shape);
  m.growing = true;
  std::string temp = state_->temp_path + "." + name + "-XXXXXX";
  m.fd = ::mkstemp(temp.data());
  if (m.fd < 0) ThrowErrno("cannot create a temporary file next to", state_->path);
  ::unlink(temp.c_str());  // lives on through m.fd; nothing left behind by a crash
  state_->members.push_back(std::move(m));
  return state_->members.size() - 1;
}

void StreamingNpzWriter::Append(std::size_t growing_array, std::span<const std::byte> frame) {
  if (state_->closed) throw std::logic_error("npz: Append after Close");
  State::Member& m = state_->members.at(growing_array);
  if (!m.growing || frame.size() != Product(m.shape) * m.item_bytes) {
    throw std::logic_error("npz: a frame of " + std::to_string(frame.size()) +
                           " bytes for array '" + m.name + "' of " +
                           ItemBytesOfDescr(m.descr, m.item_bytes));
  }
  m.data.insert(m.data.end(), frame.begin(), frame.end());
  ++m.frames;
  if (m.data.size() >= kBufferBytes) {
    try {
      state_->Flush(m);
    } catch (...) {
      state_->Discard();
      throw;
    }
  }
}

void StreamingNpzWriter::Close() {
  if (state_->closed) throw std::logic_error("npz: Close called twice");
  State& s = *state_;
  try {
    s.WriteZip();
    if (::fsync(s.zip_fd) != 0) ThrowErrno("cannot write", s.temp_path);
    struct stat info {};
    if (!s.overwrite && ::stat(s.path.c_str(), &info) == 0) {
      throw std::runtime_error("'" + s.path + "' appeared while recording (not overwritten)");
    }
    if (::rename(s.temp_path.c_str(), s.path.c_str()) != 0) {
      ThrowErrno("cannot rename the finished recording to", s.path);
    }
  } catch (...) {
    s.Discard();
    throw;
  }
  const int fd = s.zip_fd;
  s.zip_fd = -1;  // renamed: Discard must not unlink it
  s.Discard();
  if (::close(fd) != 0) ThrowErrno("cannot close", s.path);
}

void StreamingNpzWriter::Discard() {
  if (!state_->closed) state_->Discard();
}

bool StreamingNpzWriter::closed() const { return state_->closed; }
const std::string& StreamingNpzWriter::path() const { return state_->path; }

}  // namespace manyworlds::npz
