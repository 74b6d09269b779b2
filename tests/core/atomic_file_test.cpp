// AtomicFile: exclusive unique temporary files, renamed into place, removed
// on failure and on SIGINT/SIGTERM.
#include "stochtex/core/atomic_file.h"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/stat.h>

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

// Issue "Hostile input on the new surfaces", item 5: a writer that opens its
// file by name (FFmpeg) gets it in a folder only this process writes (0700),
// removed with the file on every path and on a signal.
TEST_F(AtomicFileTest, APrivateFolderHoldsTheFileAndGoesWithIt) {
    const fs::path target = dir_ / "clip.mp4";
    {
        AtomicFile f(target.string(), "", AtomicFile::Placement::PrivateFolder);
        const fs::path folder = fs::path(f.tempPath()).parent_path();
        EXPECT_EQ(folder.parent_path(), dir_);
        EXPECT_EQ(fs::path(f.tempPath()).filename(), "clip.mp4");
        EXPECT_EQ(fs::status(folder).permissions() & fs::perms::all, fs::perms::owner_all);
        f.write("frames");
        f.commit();
    }
    EXPECT_EQ(contents(target), "frames");
    EXPECT_EQ(entries(dir_), 1u);  // the folder went with the commit
    { AtomicFile f(target.string(), "", AtomicFile::Placement::PrivateFolder); }
    EXPECT_EQ(entries(dir_), 1u);  // and without one
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    const auto interrupted = [&] {
        std::signal(SIGTERM, SIG_DFL);
        installTempFileCleanup();
        AtomicFile f((dir_ / "b.mp4").string(), "", AtomicFile::Placement::PrivateFolder);
        f.write("partial");
        std::raise(SIGTERM);
        std::_Exit(0);
    };
    EXPECT_EXIT(interrupted(), testing::KilledBySignal(SIGTERM), "");
    EXPECT_EQ(entries(dir_), 1u) << "the signal left the private folder or its file";
}

// Run as root, a rename over a device node or a FIFO replaces it: anything
// but a regular file (or a link, which the rename replaces itself) is refused.
TEST_F(AtomicFileTest, OnlyARegularFileIsReplaced) {
    const fs::path fifo = dir_ / "pipe.png";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_STREQ(test::inputErrorOf([&] { AtomicFile f(fifo.string()); }).what(),
                 (fifo.string() + ": is a FIFO; only a regular file is replaced by an output").c_str());
    EXPECT_STREQ(test::inputErrorOf([&] { checkOutputFile(fifo.string()); }).what(),
                 (fifo.string() + ": is a FIFO; only a regular file is replaced by an output").c_str());
    EXPECT_STREQ(test::inputErrorOf([&] { checkOutputFile("/dev/null"); }).what(),
                 "/dev/null: is a character device; only a regular file is replaced by an output");
    EXPECT_TRUE(fs::is_fifo(fifo));
    // Replaced between the check and the rename: refused at the rename too.
    AtomicFile f((dir_ / "late.png").string());
    f.write("bytes");
    ASSERT_EQ(::mkfifo((dir_ / "late.png").c_str(), 0600), 0);
    EXPECT_NE(std::string(test::inputErrorOf([&] { f.commit(); }).what()).find("is a FIFO"), std::string::npos);
    EXPECT_TRUE(fs::is_fifo(dir_ / "late.png"));
}

// A write past a file-size limit fails (EFBIG) instead of killing the process
// with SIGXFSZ, which left the temporary file behind.
TEST_F(AtomicFileTest, AFileSizeLimitIsAnErrorThatLeavesNothing) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    const auto overLimit = [&] {
        installTempFileCleanup();
        rlimit limit;
        limit.rlim_cur = limit.rlim_max = 4096;
        setrlimit(RLIMIT_FSIZE, &limit);
        try {
            AtomicFile f((dir_ / "big.bin").string());
            f.write(std::string(8192, 'x'));
            std::_Exit(3);  // not reached: the write fails
        } catch (const InputError& e) {
            std::_Exit(std::string(e.what()).find("File too large") != std::string::npos ? 0 : 4);
        }
    };
    EXPECT_EXIT(overLimit(), testing::ExitedWithCode(0), "");
    EXPECT_EQ(entries(dir_), 0u);
}
