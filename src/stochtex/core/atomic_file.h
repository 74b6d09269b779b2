#pragma once
// Output files that appear under their name complete or not at all.
//
// An AtomicFile is a temporary file created exclusively (O_CREAT | O_EXCL |
// O_NOFOLLOW, a fresh random name `.<name>.<hex>.tmp`) in the target's
// folder, so it never follows a planted symlink and two runs writing the same
// target never share one; commit() renames it over the target, and anything
// else (an exception, the destructor) removes it. While it exists its path is
// registered, and installTempFileCleanup() makes SIGINT, SIGTERM and SIGHUP
// remove every registered file before the process dies of the signal (exit
// status 128 + signal), so an interrupted command leaves no temporary file.
// Every file the library and the CLI write goes through this (writeFileAtomic,
// writeImage, PngStreamWriter, the MP4 writer).
#include <cstdint>
#include <string>
#include <string_view>

namespace stochtex {

class AtomicFile {
public:
    // Where the temporary file is made: beside the target, or inside a
    // folder of its own (0700, `.<name>.<hex>.tmp`, removed with it) for a
    // writer that opens the file by name rather than through the descriptor
    // (FFmpeg's muxer, which reopens an MP4 to move its index first): no one
    // else can plant a link under that name there.
    enum class Placement { Beside, PrivateFolder };
    // Throws InputError naming `path` when its folder is missing or not
    // writable, or when `path` names something a rename must not replace (a
    // device, a FIFO, a socket, a folder). `suffix` ends the temporary name,
    // for writers that choose the format from it (an MP4 encoder needs ".mp4").
    explicit AtomicFile(const std::string& path, const std::string& suffix = ".tmp",
                        Placement placement = Placement::Beside);
    ~AtomicFile();  // removes the temporary file unless commit() succeeded
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    const std::string& path() const { return path_; }
    const std::string& tempPath() const { return temp_; }

    // Appends bytes; throws InputError (disk full, I/O error).
    void write(std::string_view bytes);
    // Overwrites bytes written before, at `offset` from the start (a table
    // of contents known only at the end); the end of the file stays.
    void writeAt(uint64_t offset, std::string_view bytes);
    // The descriptor passes to the caller (e.g. for fdopen), who closes it
    // before commit(); for writers that open tempPath() by name, close it.
    int releaseDescriptor();
    // Closes the file if still open and renames it over path(); throws
    // InputError on failure (the temporary file is then removed).
    void commit();

private:
    std::string path_, temp_;
    int fd_ = -1;
    std::string folder_;  // Placement::PrivateFolder's folder, else empty
    int slot_ = -1;       // in the signal-cleanup registry; -1: not registered
    int folderSlot_ = -1;
    bool committed_ = false;
};

// Checks, before any work, that a file can be written where `path` names it:
// InputError unless its folder exists and is writable and `path` is absent,
// a regular file or a link (not a folder, device, FIFO or socket).
void checkOutputFile(const std::string& path);

// Writes bytes atomically (an AtomicFile written and committed).
void writeFileAtomic(const std::string& path, const std::string& bytes);

// Installs the SIGINT/SIGTERM/SIGHUP handlers that remove the live temporary
// files and then re-raise the signal with its default action. Signals the
// process ignores (e.g. SIGHUP under nohup) stay ignored. SIGXFSZ is ignored,
// so that a write past a file-size limit fails (EFBIG) and is reported like
// a full disk. Call once, early.
void installTempFileCleanup();

// Removes every live temporary file (and private folder) now. For a process
// about to end without unwinding (a watchdog's overrun, core/watchdog.h);
// async-signal-safe (unlink and rmdir only).
void removeLiveTempFiles();

}  // namespace stochtex
