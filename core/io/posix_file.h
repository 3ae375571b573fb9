// Small POSIX steps shared by the writers in core/io: writing a whole buffer to a
// descriptor, flushing a folder so a rename in it survives a power cut, and naming.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace inkray::posix {

// False with errno set when a write fails (EINTR is retried).
bool write_all(int fd, std::string_view data);
// Makes renames and removals in `dir` durable; failure only weakens durability, so it is ignored.
void sync_directory(const std::filesystem::path& dir);
// The folder a file is in ("." for a bare name).
std::filesystem::path folder_of(const std::filesystem::path& file);
// 8 lower-case hex digits, different on every call.
std::string random_hex8();
// 8 lower-case hex digits naming this machine (a hash of its host name): a temporary
// carries it, so a process id is only ever tested on the machine it belongs to.
const std::string& host_tag();
// True when process `pid` is known to be gone: kill(pid, 0) fails with ESRCH (EPERM means
// it lives under another user).
bool process_is_gone(long pid);

}  // namespace inkray::posix
