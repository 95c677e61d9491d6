#include "pipeline/tile_journal.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "io/atomic_file.h"
#include "io/byte_stream.h"

namespace bounce {
namespace fs = std::filesystem;
namespace {

constexpr char kMagic[8] = {'B', 'N', 'C', 'T', 'I', 'L', 'E', 'S'};
constexpr uint32_t kRecordMagic = 0x454c4954u;  // "TILE"
constexpr std::size_t kRecordHead = 16;         // magic, stage, tile, payload bytes

std::vector<unsigned char> header(const nlohmann::json& key) {
  const std::string text = key.dump();
  const std::span<const unsigned char> keyBytes(reinterpret_cast<const unsigned char*>(text.data()),
                                                text.size());
  ByteWriter w;
  w.raw(kMagic, sizeof kMagic);
  w.u32(kTileJournalVersion);
  w.u32(static_cast<uint32_t>(text.size()));
  w.raw(text.data(), text.size());
  w.u64(fnv1a64(keyBytes));
  return w.take();
}

std::vector<unsigned char> record(const TileRecord& r) {
  ByteWriter w;
  w.u32(kRecordMagic);
  w.u32(static_cast<uint32_t>(r.stage));
  w.u32(r.tile);
  w.u32(static_cast<uint32_t>(r.bytes.size()));
  w.raw(r.bytes.data(), r.bytes.size());
  w.u64(fnv1a64(w.bytes()));
  return w.take();
}

// Every byte of the whole buffer out, or the reason.
void writeAll(int fd, const std::vector<unsigned char>& bytes, const fs::path& file) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw std::runtime_error(file.string() + ": cannot append a tile: " + std::strerror(errno));
    done += static_cast<std::size_t>(n);
  }
}

int openForAppend(const fs::path& file, uint64_t keep) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0)
    throw std::runtime_error(file.string() + ": cannot open the journal: " + std::strerror(errno));
  if (::ftruncate(fd, static_cast<off_t>(keep)) != 0 ||
      ::lseek(fd, static_cast<off_t>(keep), SEEK_SET) < 0) {
    const std::string why = std::strerror(errno);
    ::close(fd);
    throw std::runtime_error(file.string() +
                             ": cannot cut the journal after its whole records: " + why);
  }
  return fd;
}

// The header's key; leaves `r` after it.
nlohmann::json readKey(ByteReader& r) {
  const fs::path& file = r.file();
  if (r.remaining() < sizeof kMagic || !r.matches(kMagic, sizeof kMagic))
    throw LoadError(file, "not a bounce tile journal (bad magic)");
  const uint32_t version = r.u32("the version");
  if (version != kTileJournalVersion)
    throw LoadError(file, "journal version " + std::to_string(version) + ", this build writes " +
                              std::to_string(kTileJournalVersion) +
                              ": bake again without --resume");
  const uint32_t keyBytes = r.u32("the key's length");
  const std::span<const unsigned char> keyText = r.bytes(keyBytes, "the key");
  if (r.u64("the key's check") != fnv1a64(keyText))
    throw LoadError(file, "its key fails its check: damaged");
  nlohmann::json key = nlohmann::json::parse(keyText.begin(), keyText.end(), nullptr, false);
  if (!key.is_object()) throw LoadError(file, "its key is not a JSON object: damaged");
  return key;
}

std::vector<unsigned char> readAll(const fs::path& file, std::size_t most) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw LoadError(file, fs::exists(file) ? "cannot be read" : "missing");
  std::vector<unsigned char> bytes(most);
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(most));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return bytes;
}

}  // namespace

nlohmann::json readTileJournalKey(const fs::path& file) {
  // A key is a few hundred bytes; 1 MiB bounds what a damaged length can ask for.
  const std::vector<unsigned char> bytes = readAll(file, std::size_t{1} << 20);
  ByteReader r(file, bytes);
  return readKey(r);
}

TileJournal readTileJournal(const fs::path& file) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(file, ec);
  const std::vector<unsigned char> bytes = readAll(file, ec ? 0 : static_cast<std::size_t>(size));
  ByteReader r(file, bytes);
  TileJournal journal;
  journal.key = readKey(r);
  journal.validBytes = r.position();
  // Records up to the first one that is cut or fails its check.
  while (r.remaining() >= kRecordHead + 8) {
    const std::span<const unsigned char> head = r.bytes(kRecordHead, "a record");
    ByteReader h(file, head);
    if (h.u32("") != kRecordMagic) break;
    TileRecord record;
    const uint32_t stage = h.u32("");
    record.tile = h.u32("");
    const uint32_t payloadBytes = h.u32("");
    if (stage != static_cast<uint32_t>(TileStage::Irradiance) &&
        stage != static_cast<uint32_t>(TileStage::Visibility))
      break;
    if (r.remaining() < static_cast<std::size_t>(payloadBytes) + 8) break;
    const std::span<const unsigned char> payload = r.bytes(payloadBytes, "a payload");
    const uint64_t check = r.u64("a record's check");
    if (check != fnv1a64(payload, fnv1a64(head))) break;
    record.stage = static_cast<TileStage>(stage);
    record.bytes.assign(payload.begin(), payload.end());
    record.source = file;
    journal.records.push_back(std::move(record));
    journal.validBytes = r.position();
  }
  journal.droppedBytes = bytes.size() - journal.validBytes;
  return journal;
}

void checkTileJournalKey(const fs::path& file, const nlohmann::json& found,
                         const nlohmann::json& expected, std::span<const char* const> ignored) {
  const auto isIgnored = [&](const std::string& name) {
    for (const char* i : ignored)
      if (name == i) return true;
    return false;
  };
  for (auto field = expected.begin(); field != expected.end(); ++field) {
    if (isIgnored(field.key())) continue;
    const auto there = found.find(field.key());
    if (there == found.end())
      throw LoadError(file, "made by another version of bounce (its key has no \"" + field.key() +
                                "\"): bake again without --resume");
    if (*there != field.value() && field.key().ends_with("Format"))
      throw LoadError(file, "made by another version of bounce (its " + field.key() + " is " +
                                there->dump() + ", this build's is " + field.value().dump() +
                                "): bake again without --resume");
    if (*there != field.value())
      throw LoadError(file, "made for another bake: its " + field.key() + " is " + there->dump() +
                                ", this bake's is " + field.value().dump());
  }
  for (auto field = found.begin(); field != found.end(); ++field)
    if (!expected.contains(field.key()))
      throw LoadError(file, "made by another version of bounce (its key has \"" + field.key() +
                                "\"): bake again without --resume");
}

TileJournalWriter::TileJournalWriter(const fs::path& file, const nlohmann::json& key)
    : file_(file) {
  writeFileAtomically(file, header(key));
  fd_ = openForAppend(file, header(key).size());
}

TileJournalWriter::TileJournalWriter(const fs::path& file, const TileJournal& journal)
    : file_(file), fd_(openForAppend(file, journal.validBytes)) {}

TileJournalWriter::~TileJournalWriter() {
  if (fd_ >= 0) ::close(fd_);
}

void TileJournalWriter::append(const TileRecord& r) {
  const std::vector<unsigned char> bytes = record(r);
  const std::lock_guard<std::mutex> lock(mutex_);
  writeAll(fd_, bytes, file_);
}

}  // namespace bounce
