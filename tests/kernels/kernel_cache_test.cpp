// The disk cache of compiled kernels (host/kernels/kernel_cache.h): what it stores comes back only for
// the same key; a corrupt, truncated, spliced or foreign file is a miss and is rewritten; a cache that
// cannot be written is no cache, never an error; no temporary file is left behind.

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "kernels/kernel_cache.h"
#include "kernels/kernel_compiler.h"
#include "kernels/kernel_cache_entry.h"
#include "kernels/shader_compiler.h"
#include "fuzz/kernel_cache_fuzz_input.h"
#include "support/temporary_directory_test.h"
#include "support/test_paths.h"
#include "util/build_version.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

// Real SPIR-V, small: `extra` more statements make a longer kernel, `value` another one of the same length.
std::vector<std::uint32_t> smallKernel(int value, int extra = 0) {
    std::string source =
        "#version 450\nlayout(local_size_x = 1) in;\nlayout(std430, binding = 0) buffer Out { uint values[]; };\n"
        "void main() {\n    values[gl_GlobalInvocationID.x] = " +
        std::to_string(value) + "u;\n";
    for (int i = 0; i < extra; ++i) {
        source += "    values[" + std::to_string(i + 1) + "] += " + std::to_string(i) + "u;\n";
    }
    return compileComputeShader(source + "}\n", "test kernel");
}

std::string readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

void writeBytes(const fs::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

class KernelCacheTest : public test::TemporaryDirectoryTest {
protected:
    // A cache whose reports are kept in reports_ (one line each).
    KernelCache cache(const fs::path& directory, std::uint64_t maxBytes = KernelCache::kDefaultMaxBytes) {
        return KernelCache(directory, maxBytes, [this](const std::string& line) { reports_.push_back(line); });
    }
    // Whether the only report so far names `file` and says `reason`.
    ::testing::AssertionResult reportedOnce(const fs::path& file, const std::string& reason) const {
        if (reports_.size() == 1 && reports_[0].find("'" + file.string() + "'") != std::string::npos &&
            reports_[0].find(reason) != std::string::npos && reports_[0].starts_with("hexray: note: kernel cache")) {
            return ::testing::AssertionSuccess();
        }
        ::testing::AssertionResult failure = ::testing::AssertionFailure();
        failure << "expected one report naming " << file << " and saying \"" << reason << "\"; got:";
        for (const std::string& line : reports_) {
            failure << "\n" << line;
        }
        return failure;
    }
    std::vector<fs::path> files() const {
        std::vector<fs::path> found;
        for (const auto& entry : fs::directory_iterator(dir_ / "cache")) {
            found.push_back(entry.path());
        }
        return found;
    }
    // The file `key` is stored in (stored once to find it, then removed).
    fs::path entryName(const KernelCache& cache, const std::string& key) const {
        cache.store(key, smallKernel(1));
        const fs::path file = files().front();
        fs::remove(file);
        return file;
    }

    std::vector<std::string> reports_;
};

const std::vector<std::uint32_t>& kSpirv() {
    static const std::vector<std::uint32_t> spirv = smallKernel(42);
    return spirv;
}

TEST_F(KernelCacheTest, GivesBackWhatItStoredForTheSameKeyOnly) {
    const KernelCache cache = this->cache(dir_ / "cache");
    EXPECT_FALSE(cache.load("key"));
    cache.store("key", kSpirv());
    EXPECT_EQ(cache.load("key"), kSpirv());
    EXPECT_FALSE(cache.load("another key"));
    ASSERT_EQ(files().size(), 1u);  // and no temporary file
}

TEST_F(KernelCacheTest, ACorruptOrTruncatedFileIsAMissAndIsRewritten) {
    const KernelCache cache = this->cache(dir_ / "cache");
    cache.store("key", kSpirv());
    const fs::path file = files().front();
    const auto size = fs::file_size(file);
    fs::resize_file(file, size - 3);
    EXPECT_FALSE(cache.load("key"));
    EXPECT_TRUE(reportedOnce(file, "removed: its SHA-256 checksum does not match its contents"));
    reports_.clear();
    std::ofstream(file, std::ios::binary) << "garbage";
    EXPECT_FALSE(cache.load("key"));
    EXPECT_TRUE(reportedOnce(file, "removed: not a kernel cache file of this hexray (no HXKERNL2 header)"));
    cache.store("key", kSpirv());
    EXPECT_EQ(cache.load("key"), kSpirv());
}

TEST_F(KernelCacheTest, AFileOfAnotherKeyWithTheSameNameIsAMiss) {
    // Keys are compared in full: a file holds its key, whatever its name.
    const KernelCache cache = this->cache(dir_ / "cache");
    cache.store("key", kSpirv());
    const fs::path file = files().front();
    const KernelCache other(dir_ / "other");
    other.store("not the key", kSpirv());
    fs::copy_file(fs::directory_iterator(dir_ / "other")->path(), file, fs::copy_options::overwrite_existing);
    EXPECT_FALSE(cache.load("key"));
    EXPECT_TRUE(reportedOnce(file, "removed: it holds another kernel's key"));
}

TEST_F(KernelCacheTest, OneEntrysKeyWithAnotherEntrysSpirvIsAMiss) {
    // Two real entries whose keys have the same length: the first's bytes up to the end of its key,
    // then the second's from the end of its key on (its SPIR-V), under the first's name.
    const KernelCache cache = this->cache(dir_ / "cache");
    const std::vector<std::uint32_t> first = smallKernel(1);
    const std::vector<std::uint32_t> second = smallKernel(2, 3);
    cache.store("scene A's key", first);
    const fs::path firstFile = files().front();
    const std::string firstBytes = readBytes(firstFile);
    fs::remove(firstFile);
    cache.store("scene B's key", second);
    const std::string secondBytes = readBytes(files().front());
    const std::size_t firstKeyEnd = firstBytes.find("scene A's key") + 13;
    const std::size_t secondKeyEnd = secondBytes.find("scene B's key") + 13;
    ASSERT_NE(firstKeyEnd, std::string::npos);
    ASSERT_NE(secondKeyEnd, std::string::npos);
    writeBytes(firstFile, firstBytes.substr(0, firstKeyEnd) + secondBytes.substr(secondKeyEnd));
    EXPECT_FALSE(cache.load("scene A's key"));
    EXPECT_TRUE(reportedOnce(firstFile, "removed: its SHA-256 checksum does not match its contents"));
    EXPECT_FALSE(fs::exists(firstFile));
    EXPECT_EQ(cache.load("scene B's key"), second);
}

TEST_F(KernelCacheTest, EverySingleBitFlipIsAMissOrTheSameSpirv) {
    const KernelCache cache = this->cache(dir_ / "cache");
    cache.store("k", kSpirv());
    const fs::path file = files().front();
    const std::string original = readBytes(file);
    std::size_t misses = 0;
    for (std::size_t bit = 0; bit < original.size() * 8; ++bit) {
        std::string flipped = original;
        flipped[bit / 8] = char(flipped[bit / 8] ^ (1 << (bit % 8)));
        writeBytes(file, flipped);
        const auto loaded = cache.load("k");
        if (loaded) {
            ASSERT_EQ(*loaded, kSpirv()) << "bit " << bit;
        } else {
            ++misses;
            ASSERT_FALSE(fs::exists(file)) << "bit " << bit << ": a bad entry is removed";
            ASSERT_TRUE(reportedOnce(file, "removed: ")) << "bit " << bit;
            reports_.clear();
        }
    }
    EXPECT_EQ(misses, original.size() * 8);  // the checksum or the header catches each one
}

TEST_F(KernelCacheTest, AnIdBoundOfAllOnesIsAMiss) {
    // The SPIR-V header's fourth word: a driver that trusts it allocates 2^32 ids.
    const KernelCache cache = this->cache(dir_ / "cache");
    std::vector<std::uint32_t> spirv = kSpirv();
    spirv[3] = 0xFFFFFFFFu;
    cache.store("key", spirv);
    const fs::path file = files().front();
    EXPECT_FALSE(cache.load("key"));
    EXPECT_TRUE(reportedOnce(file, "removed: its SPIR-V fails validation: "));
    EXPECT_TRUE(files().empty());
}

TEST_F(KernelCacheTest, AFifoAtAnEntrysNameIsAMissAndIsRemoved) {
    // No writer ever opens it: a blocking open would wait for ever.
    const KernelCache cache = this->cache(dir_ / "cache");
    const fs::path file = entryName(cache, "key");
    ASSERT_EQ(::mkfifo(file.c_str(), 0600), 0);
    EXPECT_FALSE(cache.load("key"));
    EXPECT_TRUE(reportedOnce(file, "removed: it is a FIFO, not a regular file"));
    EXPECT_FALSE(fs::exists(fs::symlink_status(file)));
    cache.store("key", kSpirv());
    EXPECT_EQ(cache.load("key"), kSpirv());
}

TEST_F(KernelCacheTest, ASymlinkAtAnEntrysNameIsAMissAndOnlyTheLinkIsRemoved) {
    const KernelCache cache = this->cache(dir_ / "cache");
    const fs::path file = entryName(cache, "key");
    fs::create_symlink("/dev/zero", file);  // endless zeros: read to the end, they fill the memory
    EXPECT_FALSE(cache.load("key"));
    EXPECT_TRUE(reportedOnce(file, "removed: it is a symbolic link"));
    EXPECT_FALSE(fs::exists(fs::symlink_status(file)));
    EXPECT_TRUE(fs::exists("/dev/zero"));

    // A link to a valid entry elsewhere is refused too, and its target stays.
    const KernelCache elsewhere(dir_ / "elsewhere");
    elsewhere.store("key", kSpirv());
    const fs::path target = fs::directory_iterator(dir_ / "elsewhere")->path();
    fs::create_symlink(target, file);
    reports_.clear();
    EXPECT_FALSE(cache.load("key"));
    EXPECT_TRUE(reportedOnce(file, "removed: it is a symbolic link"));
    EXPECT_FALSE(fs::exists(fs::symlink_status(file)));
    EXPECT_EQ(elsewhere.load("key"), kSpirv());
}

TEST_F(KernelCacheTest, AFileLargerThanAnyEntryIsRefusedBeforeItIsRead) {
    const KernelCache cache = this->cache(dir_ / "cache");
    const fs::path file = entryName(cache, "key");
    writeBytes(file, "");
    fs::resize_file(file, kMaxKernelCacheEntryBytes + 1);  // sparse: no disk used
    EXPECT_FALSE(cache.load("key"));
    EXPECT_TRUE(reportedOnce(file, "removed: it holds 16777217 bytes, more than an entry may (16 MiB)"));
    EXPECT_FALSE(fs::exists(file));
}

TEST_F(KernelCacheTest, ADirectoryAtAnEntrysNameIsAMissAndIsRemovedWithoutFollowingLinks) {
    const KernelCache cache = this->cache(dir_ / "cache");
    const fs::path file = entryName(cache, "key");
    fs::create_directories(file / "inner" / "deeper");
    writeBytes(file / "inner" / "a-file", "x");
    writeBytes(dir_ / "outside", "keep me");
    fs::create_directory(dir_ / "outside-directory");
    writeBytes(dir_ / "outside-directory" / "kept", "keep me too");
    fs::create_symlink(dir_ / "outside", file / "link-to-a-file");
    fs::create_directory_symlink(dir_ / "outside-directory", file / "inner" / "link-to-a-directory");
    EXPECT_FALSE(cache.load("key"));
    EXPECT_TRUE(reportedOnce(file, "removed: it is a directory, not a regular file"));
    EXPECT_FALSE(fs::exists(fs::symlink_status(file)));
    EXPECT_EQ(readBytes(dir_ / "outside"), "keep me");
    EXPECT_EQ(readBytes(dir_ / "outside-directory" / "kept"), "keep me too");
    cache.store("key", kSpirv());
    EXPECT_EQ(cache.load("key"), kSpirv());
}

TEST_F(KernelCacheTest, LeastRecentlyUsedEntriesGoFirstToKeepTheBound) {
    const std::vector<std::uint32_t> spirv = smallKernel(7, 20);
    {
        const KernelCache probe(dir_ / "probe");
        probe.store("entry 0", spirv);
    }
    const std::uintmax_t entryBytes = fs::file_size(fs::directory_iterator(dir_ / "probe")->path());
    // Room for three entries (the keys have the same length, so the entries the same size).
    const KernelCache cache = this->cache(dir_ / "cache", 3 * entryBytes + entryBytes / 2);
    // Entries 0, 1, 2, last used in that order (set explicitly: the clock's grain is coarse).
    const auto hourAgo = fs::file_time_type::clock::now() - std::chrono::hours(1);
    for (int i = 0; i < 3; ++i) {
        cache.store("entry " + std::to_string(i), spirv);
    }
    for (const fs::path& file : files()) {
        const std::string bytes = readBytes(file);
        const int i = bytes[bytes.find("entry ") + 6] - '0';
        fs::last_write_time(file, hourAgo + std::chrono::minutes(i));
    }
    ASSERT_EQ(cache.load("entry 0"), spirv);  // now the most recently used
    cache.store("entry 3", spirv);            // over the bound: the least recently used goes, entry 1
    EXPECT_EQ(files().size(), 3u);
    EXPECT_EQ(cache.load("entry 0"), spirv);
    EXPECT_FALSE(cache.load("entry 1"));
    EXPECT_EQ(cache.load("entry 2"), spirv);
    EXPECT_EQ(cache.load("entry 3"), spirv);
    std::uintmax_t total = 0;
    for (const fs::path& file : files()) {
        total += fs::file_size(file);
    }
    EXPECT_LE(total, 3 * entryBytes + entryBytes / 2);
    EXPECT_TRUE(reports_.empty());  // eviction is no problem to report
}

TEST_F(KernelCacheTest, AStoreRemovesTemporariesAbandonedLongAgoOnly) {
    // What a process killed while storing leaves; a live writer's temporary is minutes old at most.
    fs::create_directories(dir_ / "cache");
    const fs::path abandoned = dir_ / "cache" / ".0123abcd.spv.Ab12Cd";
    const fs::path fresh = dir_ / "cache" / ".4567abcd.spv.Ef34Gh";
    const fs::path notOurs = dir_ / "cache" / "notes.txt";
    for (const fs::path& file : {abandoned, fresh, notOurs}) {
        writeBytes(file, "x");
        fs::last_write_time(file, fs::file_time_type::clock::now() - std::chrono::hours(2));
    }
    fs::last_write_time(fresh, fs::file_time_type::clock::now());
    this->cache(dir_ / "cache").store("key", kSpirv());
    EXPECT_FALSE(fs::exists(abandoned));
    EXPECT_TRUE(fs::exists(fresh));
    EXPECT_TRUE(fs::exists(notOurs));
}

TEST_F(KernelCacheTest, UsageCountsTheEntriesAndClearRemovesOnlyTheCachesFiles) {
    const KernelCache cache = this->cache(dir_ / "cache");
    cache.store("first", kSpirv());
    cache.store("second", kSpirv());
    std::uint64_t bytes = 0;
    for (const fs::path& file : files()) {
        bytes += fs::file_size(file);
    }
    ASSERT_EQ(::mkfifo((dir_ / "cache" / "0000.spv").c_str(), 0600), 0);  // at an entry's name, not an entry
    writeBytes(dir_ / "cache" / ".0000.spv.Ab12Cd", "a temporary");
    writeBytes(dir_ / "cache" / "notes.txt", "not the cache's");
    writeBytes(dir_ / "kept", "outside");
    fs::create_symlink(dir_ / "kept", dir_ / "cache" / "1111.spv");
    const KernelCache::Usage usage = cache.usage();
    EXPECT_EQ(usage.entries, 2u);
    EXPECT_EQ(usage.bytes, bytes);
    const KernelCache::Usage cleared = cache.clear();
    EXPECT_EQ(cleared.entries, 2u);
    EXPECT_EQ(cleared.bytes, bytes);
    EXPECT_EQ(files(), std::vector<fs::path>{dir_ / "cache" / "notes.txt"});
    EXPECT_EQ(readBytes(dir_ / "kept"), "outside");
    EXPECT_FALSE(cache.load("first"));
    EXPECT_TRUE(reports_.empty());
}

TEST_F(KernelCacheTest, TheBoundComesFromTheEnvironment) {
    const auto boundFor = [](const char* value) {
        ::setenv("HEXRAY_KERNEL_CACHE_MAX_SIZE", value, 1);
        const std::uint64_t bound = KernelCache::configuredMaxBytes();
        ::unsetenv("HEXRAY_KERNEL_CACHE_MAX_SIZE");
        return bound;
    };
    EXPECT_EQ(KernelCache::configuredMaxBytes(), KernelCache::kDefaultMaxBytes);
    EXPECT_EQ(boundFor(""), KernelCache::kDefaultMaxBytes);
    EXPECT_EQ(boundFor("1000"), 1000u);
    EXPECT_EQ(boundFor("64K"), 65536u);
    EXPECT_EQ(boundFor("256M"), std::uint64_t{256} << 20);
    EXPECT_EQ(boundFor("2G"), std::uint64_t{2} << 30);
    EXPECT_EQ(boundFor("0"), 0u);
    EXPECT_FALSE(KernelCache(dir_ / "cache", 0).enabled());
    for (const char* bad : {"-1", "12Q", "1.5M", "M", " 5", "5 ", "64k", "0x10", "99999999999999G"}) {
        try {
            boundFor(bad);
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const KernelCacheSettingError& error) {
            ::unsetenv("HEXRAY_KERNEL_CACHE_MAX_SIZE");
            EXPECT_NE(std::string(error.what()).find("HEXRAY_KERNEL_CACHE_MAX_SIZE: must be a size in bytes"),
                      std::string::npos);
            EXPECT_NE(std::string(error.what()).find(std::string("(got '") + bad + "')"), std::string::npos);
        }
    }
}

TEST_F(KernelCacheTest, ACacheThatCannotBeWrittenIsNoCache) {
    std::ofstream(dir_ / "a-file") << "not a directory";
    const KernelCache cache(dir_ / "a-file" / "cache");
    cache.store("key", kSpirv());  // no throw
    EXPECT_FALSE(cache.load("key"));
    const KernelCache none{fs::path()};
    none.store("key", kSpirv());
    EXPECT_FALSE(none.load("key"));
}

TEST_F(KernelCacheTest, ConcurrentWritersLeaveOneWholeFile) {
    const KernelCache cache(dir_ / "cache", KernelCache::kDefaultMaxBytes,
                            [](const std::string& line) { ADD_FAILURE() << "a whole file was refused: " << line; });
    const std::vector<std::uint32_t>& spirv = kSpirv();
    std::vector<std::jthread> writers;
    for (int i = 0; i < 8; ++i) {
        writers.emplace_back([&] {
            for (int round = 0; round < 20; ++round) {
                cache.store("key", spirv);
                const auto loaded = cache.load("key");
                EXPECT_TRUE(!loaded || *loaded == spirv);
            }
        });
    }
    writers.clear();
    EXPECT_EQ(cache.load("key"), spirv);
    EXPECT_EQ(files().size(), 1u);
}

TEST_F(KernelCacheTest, AGeneratedKernelIsCompiledOnceAndThenComesFromTheCache) {
    SceneCode code;
    code.nodes.push_back(NodeCode{});  // a plane
    code.shadowTests.emplace_back();
    const Kernel kernel{"test", std::make_shared<const SceneCode>(code), {}};
    KernelBuild first;
    KernelCompiler(KernelCache(dir_ / "cache")).spirv(kernel, &first);
    EXPECT_FALSE(first.fromDiskCache);
    EXPECT_GT(first.compileMilliseconds, 0.0);
    KernelBuild second;
    const std::vector<std::uint32_t> spirv = [&] {
        KernelCompiler compiler(KernelCache(dir_ / "cache"));
        const auto words = compiler.spirv(kernel, &second);
        return std::vector<std::uint32_t>(words.begin(), words.end());
    }();
    EXPECT_TRUE(second.fromDiskCache);
    EXPECT_EQ(second.compileMilliseconds, 0.0);
    EXPECT_EQ(spirv.front(), 0x07230203u);
}

TEST_F(KernelCacheTest, TheKeyCoversTheSourceTheCompilerAndThisBuild) {
    const std::string key = kernelCacheKey("void main() {}");
    EXPECT_TRUE(key.starts_with(std::string("hexray ") + hexrayVersion() + " (git " + hexrayGitRevision() + ")\n"))
        << key;
    EXPECT_NE(key.find(shaderCompilerFingerprint()), std::string::npos);
    EXPECT_NE(shaderCompilerFingerprint().find("SPIR-V 1.3 for Vulkan 1.1"), std::string::npos);
    EXPECT_TRUE(key.ends_with("\nvoid main() {}"));
}

TEST_F(KernelCacheTest, SpirvTheDriverRefusedIsRemovedCompiledAfreshAndStoredAgain) {
    SceneCode code;
    code.nodes.push_back(NodeCode{});
    const Kernel kernel{"test", std::make_shared<const SceneCode>(code), {}};
    KernelCompiler(this->cache(dir_ / "cache")).spirv(kernel);
    const fs::path file = files().front();
    const std::string stored = readBytes(file);
    fs::last_write_time(file, fs::file_time_type::clock::now() - std::chrono::hours(1));

    KernelCompiler compiler(this->cache(dir_ / "cache"));
    const std::span<const std::uint32_t> cached = compiler.spirv(kernel);
    EXPECT_TRUE(compiler.fromDiskCache(cached.data()));
    KernelBuild build;
    const std::span<const std::uint32_t> fresh =
        compiler.recompile(kernel, "the driver refused its SPIR-V (test)", &build);
    EXPECT_TRUE(reportedOnce(file, "removed: the driver refused its SPIR-V (test)"));
    EXPECT_FALSE(compiler.fromDiskCache(fresh.data()));
    EXPECT_TRUE(compiler.holds(fresh.data()));
    EXPECT_GT(build.compileMilliseconds, 0.0);
    EXPECT_EQ(compiler.spirv(kernel).data(), fresh.data());  // the fresh one is kept
    EXPECT_EQ(readBytes(file), stored);                      // written again: the same bytes, a new file
    EXPECT_GT(fs::last_write_time(file), fs::file_time_type::clock::now() - std::chrono::minutes(30));
}

// The kernel cache fuzzer's seeds (tests/fuzz/kernel_cache_seeds/) are valid entries of its key,
// as a file and resealed. HEXRAY_WRITE_KERNEL_CACHE_SEEDS=1 writes them afresh (after a change of
// the file's format).
TEST(KernelCacheFuzzSeeds, AreValidEntriesOfTheFuzzersKey) {
    const fs::path seeds = test::sourcePath("tests/fuzz/kernel_cache_seeds");
    const std::string entry = sealKernelCacheEntry(test::kKernelCacheFuzzKey, smallKernel(3));
    if (std::getenv("HEXRAY_WRITE_KERNEL_CACHE_SEEDS")) {
        writeBytes(seeds / "valid-entry", std::string(1, '\0') + entry);
        writeBytes(seeds / "valid-entry-resealed", std::string(1, '\1') + entry);
    }
    for (const char* name : {"valid-entry", "valid-entry-resealed"}) {
        const std::string input = readBytes(seeds / name);
        ASSERT_FALSE(input.empty()) << name;
        const std::string file =
            test::kernelCacheFileFromFuzzInput(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
        EXPECT_EQ(openKernelCacheEntry(file, test::kKernelCacheFuzzKey).problem, "")
            << name << ": run this test with HEXRAY_WRITE_KERNEL_CACHE_SEEDS=1 to write the seeds afresh";
    }
}

}  // namespace
}  // namespace hexray
