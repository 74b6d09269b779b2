#include "stochtex/core/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>

#include "stochtex/core/error.h"

namespace stochtex {
namespace fs = std::filesystem;

namespace {

// The live temporary files, readable from a signal handler: fixed storage,
// lock-free atomics, no allocation. A slot is Free, being Filled by its
// owner, or Live (the handler may unlink its path).
enum SlotState : int { kFree = 0, kFilling = 1, kLive = 2 };
constexpr int kSlots = 256;
constexpr size_t kMaxPath = 4096;
struct Slot {
    std::atomic<int> state{kFree};
    char path[kMaxPath];
};
Slot gSlots[kSlots];
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs lock-free atomics");

constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP};

// -1 when the registry is full or the path too long: the file is still
// removed on every ordinary exit path, only not on a signal.
int registerTemp(const std::string& path) {
    if (path.size() >= kMaxPath) return -1;
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (!gSlots[i].state.compare_exchange_strong(expected, kFilling)) continue;
        std::memcpy(gSlots[i].path, path.c_str(), path.size() + 1);
        gSlots[i].state.store(kLive, std::memory_order_release);
        return i;
    }
    return -1;
}

void unregisterTemp(int slot) {
    if (slot >= 0) gSlots[slot].state.store(kFree, std::memory_order_release);
}

// Async-signal-safe: unlink and rmdir only (files first, then the private
// folders that held them), then the default action (SA_RESETHAND restored
// it; the re-raised signal is delivered when the handler returns).
extern "C" void removeTempFilesAndDie(int sig) {
    const int savedErrno = errno;
    removeLiveTempFiles();
    raise(sig);
    errno = savedErrno;
}

// Blocks the cleanup signals for its lifetime, so that creating a temporary
// file and registering it happen together: a signal between the two would
// otherwise leave an unregistered file behind.
class CleanupSignalsBlocked {
public:
    CleanupSignalsBlocked() {
        sigset_t set;
        sigemptyset(&set);
        for (int sig : kCleanupSignals) sigaddset(&set, sig);
        pthread_sigmask(SIG_BLOCK, &set, &old_);
    }
    ~CleanupSignalsBlocked() { pthread_sigmask(SIG_SETMASK, &old_, nullptr); }

private:
    sigset_t old_;
};

std::string randomHex() {
    static thread_local std::mt19937_64 rng{std::random_device{}()};
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(rng()));
    return hex;
}

}  // namespace

namespace {

// InputError unless `path` is absent, a regular file or a symbolic link (a
// rename replaces the link itself): run as root, a rename over a device node
// or a FIFO would replace it.
void checkReplaceable(const std::string& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) return;
    if (S_ISREG(st.st_mode) || S_ISLNK(st.st_mode)) return;
    const char* kind = S_ISDIR(st.st_mode)    ? "a folder"
                       : S_ISCHR(st.st_mode)  ? "a character device"
                       : S_ISBLK(st.st_mode)  ? "a block device"
                       : S_ISFIFO(st.st_mode) ? "a FIFO"
                       : S_ISSOCK(st.st_mode) ? "a socket"
                                              : "not a regular file";
    throw InputError(path + ": is " + kind + "; only a regular file is replaced by an output");
}

}  // namespace

AtomicFile::AtomicFile(const std::string& path, const std::string& suffix, Placement placement) : path_(path) {
    const fs::path target(path);
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw InputError(path + ": folder " + dir.string() + " does not exist");
    checkReplaceable(path);
    // A fresh name per attempt: EEXIST means another file (or a planted link)
    // already has it, which is never ours to touch. The name is registered
    // for the signal handler before it exists: a signal delivered to another
    // thread (which the mask below does not block) while the file is being
    // created must still find it.
    for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
        // Built by appending: GCC 12 warns falsely (-Wrestrict) on "." + string.
        std::string name = ".";
        name += target.filename().string();
        name += '.';
        name += randomHex();
        CleanupSignalsBlocked blocked;
        if (placement == Placement::PrivateFolder) {
            // A folder only this process writes (0700): a writer that opens its
            // file by name (FFmpeg) cannot be handed a planted link there.
            name += ".tmp";
            folder_ = (dir / name).string();
            folderSlot_ = registerTemp(folder_);
            if (::mkdir(folder_.c_str(), 0700) != 0) {
                const int error = errno;
                unregisterTemp(folderSlot_);
                folderSlot_ = -1;
                folder_.clear();
                if (error == EEXIST) continue;
                throw InputError(path + ": cannot create a folder in " + dir.string() + ": " + std::strerror(error));
            }
            temp_ = (fs::path(folder_) / (target.filename().string() + suffix)).string();
        } else {
            name += suffix;
            temp_ = (dir / name).string();
        }
        slot_ = registerTemp(temp_);
        fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd_ < 0) {
            const int error = errno;
            unregisterTemp(slot_);
            slot_ = -1;
            if (error != EEXIST || placement == Placement::PrivateFolder)
                throw InputError(path + ": cannot create a file in " + dir.string() + ": " + std::strerror(error));
        }
    }
    if (fd_ < 0) throw InputError(path + ": cannot create a unique temporary file in " + dir.string());
}

AtomicFile::~AtomicFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) ::unlink(temp_.c_str());
    unregisterTemp(slot_);
    if (!folder_.empty()) ::rmdir(folder_.c_str());
    unregisterTemp(folderSlot_);
}

void AtomicFile::write(std::string_view bytes) {
    if (fd_ < 0) throw std::logic_error("AtomicFile::write: the descriptor was released");
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw InputError(path_ + ": write failed: " + std::strerror(errno));
        bytes.remove_prefix(size_t(n));
    }
}

void AtomicFile::writeAt(uint64_t offset, std::string_view bytes) {
    if (fd_ < 0) throw std::logic_error("AtomicFile::writeAt: the descriptor was released");
    while (!bytes.empty()) {
        const ssize_t n = ::pwrite(fd_, bytes.data(), bytes.size(), off_t(offset));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw InputError(path_ + ": write failed: " + std::strerror(errno));
        bytes.remove_prefix(size_t(n));
        offset += uint64_t(n);
    }
}

int AtomicFile::releaseDescriptor() {
    const int fd = fd_;
    fd_ = -1;
    return fd;
}

void AtomicFile::commit() {
    if (fd_ >= 0) {
        const int fd = releaseDescriptor();
        if (::close(fd) != 0) throw InputError(path_ + ": write failed: " + std::strerror(errno));
    }
    checkReplaceable(path_);  // again: it may have been replaced while the file was written
    if (::rename(temp_.c_str(), path_.c_str()) != 0)
        throw InputError(path_ + ": cannot move the finished file into place: " + std::strerror(errno));
    committed_ = true;
    unregisterTemp(slot_);
    slot_ = -1;
}

void checkOutputFile(const std::string& path) {
    const fs::path p(path);
    std::error_code ec;
    const fs::path folder = p.has_parent_path() ? p.parent_path() : fs::path(".");
    if (!fs::is_directory(folder, ec)) throw InputError(path + ": directory " + folder.string() + " does not exist");
    checkReplaceable(path);
    if (::access(folder.c_str(), W_OK) != 0)
        throw InputError(path + ": directory " + folder.string() + " is not writable");
}

void writeFileAtomic(const std::string& path, const std::string& bytes) {
    AtomicFile file(path);
    file.write(bytes);
    file.commit();
}

void installTempFileCleanup() {
    // Over a file-size limit (ulimit -f) a write then fails with EFBIG, which
    // the writers report, and the temporary file is removed; SIGXFSZ's
    // default action would kill the process and leave it.
    signal(SIGXFSZ, SIG_IGN);
    for (int sig : kCleanupSignals) {
        struct sigaction old {};
        sigaction(sig, nullptr, &old);
        if (old.sa_handler == SIG_IGN) continue;
        struct sigaction action {};
        action.sa_handler = removeTempFilesAndDie;
        sigemptyset(&action.sa_mask);
        for (int other : kCleanupSignals) sigaddset(&action.sa_mask, other);
        action.sa_flags = SA_RESETHAND;
        sigaction(sig, &action, nullptr);
    }
}

void removeLiveTempFiles() {
    for (Slot& s : gSlots)
        if (s.state.load(std::memory_order_acquire) == kLive) unlink(s.path);
    for (Slot& s : gSlots)
        if (s.state.load(std::memory_order_acquire) == kLive) rmdir(s.path);
}

}  // namespace stochtex
