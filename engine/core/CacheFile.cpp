#include "core/CacheFile.h"

#include "core/ContentHash.h"
#include "core/Log.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <fstream>

namespace dermis {
namespace {

namespace fs = std::filesystem;

struct Header {
    char magic[8];
    uint32_t version;
    uint32_t zero0;
    uint64_t key;
    uint64_t payloadBytes;
    uint64_t payloadHash;
    uint64_t zero1;
};
static_assert(sizeof(Header) == 48, "the header is packed by layout, without padding");

template <class Bytes>
uint64_t totalSize(const std::vector<Bytes>& parts) {
    uint64_t total = 0;
    for (const Bytes& part : parts) total += part.size;
    return total;
}

template <class Bytes>
uint64_t payloadHash(const std::vector<Bytes>& parts) {
    ContentHash hash;
    for (const Bytes& part : parts) hash.bytes(part.data, part.size);
    return hash.value();
}

}  // namespace

std::string cacheFileName(const std::string& prefix, uint64_t key) {
    return prefix + hex16(key) + ".bin";
}

Status writeCacheFile(const fs::path& file, const CacheFileKind& kind, uint64_t key, const std::vector<ConstBytes>& parts) {
    std::error_code error;
    fs::create_directories(file.parent_path(), error);
    if (error) return makeError(file.parent_path().string(), "cannot create the cache directory: " + error.message());
    Header header{};
    std::memcpy(header.magic, kind.magic.data(), sizeof header.magic);
    header.version = kind.version;
    header.key = key;
    header.payloadBytes = totalSize(parts);
    header.payloadHash = payloadHash(parts);
    // Unique per process and call, in the same directory so the rename is atomic.
    static std::atomic<unsigned> sTemporaryCounter{0};
    const fs::path temporary = file.string() + ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(sTemporaryCounter++);
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(&header), sizeof header);
        for (const ConstBytes& part : parts) out.write(static_cast<const char*>(part.data), std::streamsize(part.size));
        out.close();
        if (!out) {
            fs::remove(temporary, error);
            return makeError(temporary.string(), "cannot be written");
        }
    }
    fs::rename(temporary, file, error);
    if (error) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        return makeError(file.string(), "cannot be renamed into place: " + error.message());
    }
    return success();
}

namespace {

// Opens `file` and checks its header against kind and key.
Status readHeader(std::ifstream& in, const fs::path& file, const CacheFileKind& kind, uint64_t key, Header& header) {
    in.open(file, std::ios::binary);
    if (!in) return makeError(file.string(), "cannot be opened");
    if (!in.read(reinterpret_cast<char*>(&header), sizeof header)) return makeError(file.string(), "shorter than its header");
    if (std::memcmp(header.magic, kind.magic.data(), sizeof header.magic) != 0)
        return makeError(file.string(), "not a " + kind.name + " cache file");
    if (header.version != kind.version)
        return makeError(file.string(),
                         "version " + std::to_string(header.version) + ", expected " + std::to_string(kind.version));
    if (header.key != key) return makeError(file.string(), "made from other content (another key)");
    return success();
}

Status readPayload(std::ifstream& in, const fs::path& file, const Header& header, const std::vector<MutableBytes>& parts) {
    const uint64_t expected = totalSize(parts);
    if (header.payloadBytes != expected)
        return makeError(file.string(), "holds " + std::to_string(header.payloadBytes) + " bytes of payload, expected " +
                                            std::to_string(expected));
    for (const MutableBytes& part : parts) {
        if (!in.read(static_cast<char*>(part.data), std::streamsize(part.size)))
            return makeError(file.string(), "truncated: shorter than its " + std::to_string(expected) + " bytes of payload");
    }
    if (in.peek() != std::ifstream::traits_type::eof()) return makeError(file.string(), "longer than its payload");
    if (payloadHash(parts) != header.payloadHash) return makeError(file.string(), "corrupt: the payload hash differs");
    return success();
}

}  // namespace

Status readCacheFile(const fs::path& file, const CacheFileKind& kind, uint64_t key, const std::vector<MutableBytes>& parts) {
    std::ifstream in;
    Header header{};
    if (Status opened = readHeader(in, file, kind, key, header); !opened) return opened;
    return readPayload(in, file, header, parts);
}

Status readCacheFile(const fs::path& file, const CacheFileKind& kind, uint64_t key, std::vector<uint8_t>& payload,
                     uint64_t maxBytes) {
    std::ifstream in;
    Header header{};
    if (Status opened = readHeader(in, file, kind, key, header); !opened) return opened;
    if (header.payloadBytes > maxBytes)
        return makeError(file.string(), "holds " + std::to_string(header.payloadBytes) + " bytes of payload, more than the " +
                                            std::to_string(maxBytes) + " such a file can hold");
    payload.resize(size_t(header.payloadBytes));
    return readPayload(in, file, header, {{payload.data(), payload.size()}});
}

namespace {

// What both readCacheFileOrWarn do around their read.
template <class Read>
bool readOrWarn(const fs::path& file, const CacheFileKind& kind, Read read) {
    std::error_code error;
    if (file.empty() || !fs::exists(file, error)) return false;
    if (Status status = read(); !status) {
        log::warn("ignoring the " + kind.name + " cache: " + status.error().message() + "; recomputing");
        return false;
    }
    fs::last_write_time(file, fs::file_time_type::clock::now(), error);  // used now; a read-only cache stays usable
    return true;
}

}  // namespace

bool readCacheFileOrWarn(const fs::path& file, const CacheFileKind& kind, uint64_t key, const std::vector<MutableBytes>& parts) {
    return readOrWarn(file, kind, [&] { return readCacheFile(file, kind, key, parts); });
}

bool readCacheFileOrWarn(const fs::path& file, const CacheFileKind& kind, uint64_t key, std::vector<uint8_t>& payload,
                         uint64_t maxBytes) {
    return readOrWarn(file, kind, [&] { return readCacheFile(file, kind, key, payload, maxBytes); });
}

void writeCacheFileOrWarn(const fs::path& file, const CacheFileKind& kind, uint64_t key, const std::vector<ConstBytes>& parts) {
    if (file.empty()) {
        log::warn("no cache directory for the " + kind.name + " (set DERMIS_CACHE_DIR, XDG_CACHE_HOME or HOME); not cached");
    } else if (Status written = writeCacheFile(file, kind, key, parts); !written) {
        log::warn(kind.name + " not cached: " + written.error().message());
    }
}

int removeLeastRecentlyUsed(const fs::path& directory, const std::string& prefix, int keep) {
    std::vector<std::pair<fs::file_time_type, fs::path>> files;
    std::error_code error;
    for (fs::directory_iterator it(directory, error), end; !error && it != end; it.increment(error)) {
        const std::string name = it->path().filename().string();
        if (name.size() < prefix.size() + 4 || name.compare(0, prefix.size(), prefix) != 0 ||
            name.compare(name.size() - 4, 4, ".bin") != 0)
            continue;
        std::error_code timeError;
        const fs::file_time_type time = fs::last_write_time(it->path(), timeError);
        if (!timeError) files.emplace_back(time, it->path());
    }
    std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    int removed = 0;
    for (size_t i = size_t(std::max(keep, 0)); i < files.size(); ++i) removed += fs::remove(files[i].second, error) ? 1 : 0;
    return removed;
}

}  // namespace dermis
