#pragma once
// The one way Rigsmith writes a file (guides, autosaves, exports, rig dumps,
// icons): whole or not at all, never through a planted link.
//
// A symlinked target is resolved to its final target first, so saving through
// a link writes the file it points at and keeps the link. The bytes go to a
// new temp file beside that target, ".<name>.<random>.tmp", created with
// O_CREAT | O_EXCL | O_NOFOLLOW (an existing file or link at that name is never
// opened, and two writers never share one). Every write is checked, the temp is
// fsync'ed, given the previous file's mode and (where permitted) owner, renamed
// over the target, and the folder is fsync'ed. Any failure (a full disk, EFBIG,
// EACCES, a target that is a folder or a FIFO) removes the temp, leaves the
// previous file byte-identical and returns a failed Status whose message names
// the path and the system's reason. Concurrent writers to one target: each
// rename is atomic, so the file is always one writer's whole content.
//
// A new file gets the mode 0666 minus the umask, like any created file.
#include "base/Status.h"

#include <string>
#include <string_view>
#include <vector>

namespace rs::io {

Status writeFileAtomically(const std::string& path, std::string_view bytes);

// One file of a group written together (a .gltf and its .bin).
struct FileContent {
    std::string path;
    std::string_view bytes; // the caller's, for the length of the call
};
// Writes and checks every temp file before renaming any: a failure in one
// leaves all the previous files intact. (The renames themselves follow one
// another; each is atomic.)
Status writeFilesAtomically(const std::vector<FileContent>& files);

// The path a write to `path` replaces: `path` with its symlinks followed to the
// final target (a dangling link gives the path it points at); `path` itself
// when it is not a link. Fails on a link loop.
Status resolveWriteTarget(const std::string& path, std::string& target);

} // namespace rs::io
