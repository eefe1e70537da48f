#include "io/AtomicFile.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>

#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rs::io {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxLinkHops = 40; // as the kernel's own limit (ELOOP)

Status failure(const std::string& path, const std::string& what, int error)
{
    return Status::failure(makeError({path, 0, 0}, what + ": " + std::strerror(error) + " (the previous file is untouched)"));
}

// 16 hex digits nobody can predict, so a link planted at a guessed temp name
// is unlikely to be hit at all (and O_EXCL | O_NOFOLLOW refuses it if it is).
std::string randomSuffix()
{
    unsigned long long value = 0;
    if (getrandom(&value, sizeof value, 0) != ssize_t(sizeof value)) {
        std::random_device device;
        value = (static_cast<unsigned long long>(device()) << 32) ^ device();
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", value);
    return text;
}

bool writeAll(int fd, std::string_view bytes, int& error)
{
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            error = n < 0 ? errno : ENOSPC; // a 0-byte write of a non-empty buffer: no room
            return false;
        }
        done += std::size_t(n);
    }
    return true;
}

// A temp file written, synced and closed, not yet renamed over its target.
struct PendingFile {
    std::string path;   // as asked (for messages)
    std::string target; // the resolved file the rename replaces
    std::string temp;   // empty until created
};

// Creates a temp file beside `target` that no one else has opened.
int createTemp(PendingFile& file, mode_t mode, int& error)
{
    const fs::path target(file.target);
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    for (int attempt = 0; attempt < 100; ++attempt) {
        std::string name(1, '.'); // built by appending: GCC 12 warns (-Wrestrict, falsely) on "." + string
        name.append(target.filename().string()).append(1, '.').append(randomSuffix()).append(".tmp");
        const std::string temp = (folder / name).string();
        const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, mode);
        if (fd >= 0) {
            file.temp = temp;
            return fd;
        }
        if (errno != EEXIST && errno != EINTR) {
            error = errno;
            return -1;
        }
    }
    error = EEXIST;
    return -1;
}

Status prepare(PendingFile& file, std::string_view bytes)
{
    if (file.path.empty())
        return Status::failure(makeError({}, "cannot write a file with an empty name"));
    if (Status resolved = resolveWriteTarget(file.path, file.target); resolved.failed())
        return resolved;
    struct stat previous {};
    const bool replacing = ::stat(file.target.c_str(), &previous) == 0;
    if (replacing && !S_ISREG(previous.st_mode))
        return Status::failure(makeError({file.path, 0, 0}, "cannot write: not a regular file"));
    // A replaced file's contents stay private until the temp has its mode; a new
    // file is created as any other (0666 less the umask).
    int error = 0;
    const int fd = createTemp(file, replacing ? 0600 : 0666, error);
    if (fd < 0)
        return failure(file.path, "cannot create a temporary file beside it", error);
    bool ok = writeAll(fd, bytes, error);
    if (ok && replacing) {
        // Owner where permitted (root, or a group we are in); chown before chmod, as it clears set-id bits.
        if (previous.st_uid != ::geteuid() || previous.st_gid != ::getegid())
            if (::fchown(fd, previous.st_uid, previous.st_gid) != 0 && errno == EPERM)
                (void)::fchown(fd, uid_t(-1), previous.st_gid);
        if (ok && ::fchmod(fd, previous.st_mode & 07777) != 0)
            ok = false, error = errno;
    }
    if (ok && ::fsync(fd) != 0)
        ok = false, error = errno;
    if (::close(fd) != 0 && ok)
        ok = false, error = errno;
    if (!ok) {
        ::unlink(file.temp.c_str());
        file.temp.clear();
        return failure(file.path, "cannot write", error);
    }
    return {};
}

void discard(std::vector<PendingFile>& files)
{
    for (PendingFile& f : files)
        if (!f.temp.empty())
            ::unlink(f.temp.c_str());
}

Status syncFolder(const PendingFile& file)
{
    const fs::path target(file.target);
    const std::string folder = target.has_parent_path() ? target.parent_path().string() : std::string(".");
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0)
        return {}; // a folder we may not read: the rename is done, nothing more to confirm
    const bool synced = ::fsync(fd) == 0 || errno == EINVAL || errno == EROFS; // some file systems cannot sync folders
    const int error = errno;
    ::close(fd);
    if (!synced)
        return Status::failure(makeError({file.path, 0, 0}, std::string("written, but its folder could not be synced: ") +
                                                                std::strerror(error)));
    return {};
}

} // namespace

Status resolveWriteTarget(const std::string& path, std::string& target)
{
    fs::path current(path);
    for (int hop = 0; hop <= kMaxLinkHops; ++hop) {
        std::error_code ec;
        if (!fs::is_symlink(fs::symlink_status(current, ec))) {
            target = current.string();
            return {};
        }
        const fs::path next = fs::read_symlink(current, ec);
        if (ec)
            return Status::failure(makeError({path, 0, 0}, "cannot read the link: " + ec.message()));
        current = next.is_absolute() ? next : current.parent_path() / next;
    }
    return failure(path, "cannot write through the link", ELOOP);
}

Status writeFilesAtomically(const std::vector<FileContent>& files)
{
    std::vector<PendingFile> pending;
    pending.reserve(files.size());
    for (const FileContent& f : files) {
        pending.push_back({f.path, {}, {}});
        if (Status prepared = prepare(pending.back(), f.bytes); prepared.failed()) {
            discard(pending);
            return prepared;
        }
    }
    for (std::size_t i = 0; i < pending.size(); ++i) {
        if (::rename(pending[i].temp.c_str(), pending[i].target.c_str()) != 0) {
            const int error = errno;
            discard(pending); // the renamed ones are gone from their temp names: unlink fails harmlessly
            return Status::failure(makeError({pending[i].path, 0, 0}, std::string("cannot replace the file: ") +
                                                                          std::strerror(error) + " (the previous file is untouched)"));
        }
        pending[i].temp.clear();
    }
    for (const PendingFile& f : pending)
        if (Status synced = syncFolder(f); synced.failed())
            return synced;
    return {};
}

Status writeFileAtomically(const std::string& path, std::string_view bytes)
{
    return writeFilesAtomically({FileContent{path, bytes}});
}

} // namespace rs::io
