// AtomicFile: exclusive unique temporary files, renamed into place, removed
// on failure and on SIGINT/SIGTERM.
#include "stochtex/core/atomic_file.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "stochtex/core/error.h"
#include "test_util.h"

using namespace stochtex;
namespace fs = std::filesystem;

namespace {

std::string contents(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

size_t entries(const fs::path& d) {
    size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(d)) ++n;
    return n;
}

class AtomicFileTest : public test::ScratchFolder {};

}  // namespace

TEST_F(AtomicFileTest, CommitMovesTheBytesIntoPlaceAndNothingElseRemains) {
    const fs::path target = dir_ / "out.txt";
    writeFileAtomic(target.string(), "first");
    writeFileAtomic(target.string(), "second");  // replaces
    EXPECT_EQ(contents(target), "second");
    EXPECT_EQ(entries(dir_), 1u);
}

TEST_F(AtomicFileTest, AnUncommittedFileLeavesNothing) {
    {
        AtomicFile f((dir_ / "out.txt").string());
        f.write("partial");
        EXPECT_TRUE(fs::exists(f.tempPath()));
    }
    EXPECT_EQ(entries(dir_), 0u);
}

TEST_F(AtomicFileTest, TemporaryNamesAreUniqueAndNeverFollowAPlantedLink) {
    const fs::path target = dir_ / "out.png";
    // Links at the names a fixed scheme would use, pointing at a victim.
    const fs::path victim = dir_ / "victim";
    std::ofstream(victim) << "precious";
    fs::create_symlink(victim, dir_ / "out.png.tmp");
    AtomicFile a(target.string()), b(target.string());
    EXPECT_NE(a.tempPath(), b.tempPath());
    a.write("from a");
    b.write("from b");
    a.commit();
    EXPECT_EQ(contents(target), "from a");
    b.commit();
    EXPECT_EQ(contents(target), "from b");
    EXPECT_EQ(contents(victim), "precious");
    EXPECT_FALSE(fs::is_symlink(target));
}

TEST_F(AtomicFileTest, AMissingFolderIsAnInputErrorNamingTheTarget) {
    const std::string target = (dir_ / "no" / "out.txt").string();
    const InputError e = test::inputErrorOf([&] { AtomicFile f(target); });
    EXPECT_EQ(std::string(e.what()).rfind(target + ": ", 0), 0u) << e.what();
}

TEST_F(AtomicFileTest, ATerminatingSignalRemovesLiveTemporaryFilesAndKillsWithTheSignal) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    for (int sig : {SIGTERM, SIGINT}) {
        const auto interrupted = [&] {
            std::signal(sig, SIG_DFL);  // as a shell starts a command
            installTempFileCleanup();
            AtomicFile a((dir_ / "a.png").string());
            AtomicFile b((dir_ / "b.png").string());
            a.write("partial");
            std::raise(sig);
            std::_Exit(0);  // not reached
        };
        EXPECT_EXIT(interrupted(), testing::KilledBySignal(sig), "");
        EXPECT_EQ(entries(dir_), 0u) << "signal " << sig << " left a file";
    }
}
