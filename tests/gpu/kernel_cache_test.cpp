// The disk cache of compiled kernels (host/gpu/kernel_cache.h): what it stores comes back only for
// the same key; a corrupt, truncated or foreign file is a miss and is rewritten; a cache that
// cannot be written is no cache, never an error; no temporary file is left behind.

#include <fstream>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "gpu/kernel_cache.h"
#include "gpu/kernel_compiler.h"
#include "support/temporary_directory_test.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

class KernelCacheTest : public test::TemporaryDirectoryTest {
protected:
    std::vector<fs::path> files() const {
        std::vector<fs::path> found;
        for (const auto& entry : fs::directory_iterator(dir_ / "cache")) {
            found.push_back(entry.path());
        }
        return found;
    }
};

const std::vector<std::uint32_t> kSpirv = {0x07230203u, 0x00010300u, 7u, 42u};

TEST_F(KernelCacheTest, GivesBackWhatItStoredForTheSameKeyOnly) {
    const KernelCache cache(dir_ / "cache");
    EXPECT_FALSE(cache.load("key"));
    cache.store("key", kSpirv);
    EXPECT_EQ(cache.load("key"), kSpirv);
    EXPECT_FALSE(cache.load("another key"));
    ASSERT_EQ(files().size(), 1u);  // and no temporary file
}

TEST_F(KernelCacheTest, ACorruptOrTruncatedFileIsAMissAndIsRewritten) {
    const KernelCache cache(dir_ / "cache");
    cache.store("key", kSpirv);
    const fs::path file = files().front();
    const auto size = fs::file_size(file);
    fs::resize_file(file, size - 3);
    EXPECT_FALSE(cache.load("key"));
    std::ofstream(file, std::ios::binary) << "garbage";
    EXPECT_FALSE(cache.load("key"));
    cache.store("key", kSpirv);
    EXPECT_EQ(cache.load("key"), kSpirv);
}

TEST_F(KernelCacheTest, AFileOfAnotherKeyWithTheSameNameIsAMiss) {
    // Keys are compared in full: a file holds its key, whatever its name.
    const KernelCache cache(dir_ / "cache");
    cache.store("key", kSpirv);
    const fs::path file = files().front();
    const KernelCache other(dir_ / "other");
    other.store("not the key", kSpirv);
    fs::copy_file(fs::directory_iterator(dir_ / "other")->path(), file, fs::copy_options::overwrite_existing);
    EXPECT_FALSE(cache.load("key"));
}

TEST_F(KernelCacheTest, ACacheThatCannotBeWrittenIsNoCache) {
    std::ofstream(dir_ / "a-file") << "not a directory";
    const KernelCache cache(dir_ / "a-file" / "cache");
    cache.store("key", kSpirv);  // no throw
    EXPECT_FALSE(cache.load("key"));
    const KernelCache none{fs::path()};
    none.store("key", kSpirv);
    EXPECT_FALSE(none.load("key"));
}

TEST_F(KernelCacheTest, ConcurrentWritersLeaveOneWholeFile) {
    const KernelCache cache(dir_ / "cache");
    std::vector<std::jthread> writers;
    for (int i = 0; i < 8; ++i) {
        writers.emplace_back([&] {
            for (int round = 0; round < 20; ++round) {
                cache.store("key", kSpirv);
                const auto loaded = cache.load("key");
                EXPECT_TRUE(!loaded || *loaded == kSpirv);
            }
        });
    }
    writers.clear();
    EXPECT_EQ(cache.load("key"), kSpirv);
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

}  // namespace
}  // namespace hexray
