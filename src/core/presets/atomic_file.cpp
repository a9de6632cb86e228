#include "ptz_action_server/core/presets/atomic_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace ptz_action_server
{
namespace
{
namespace fs = std::filesystem;

std::string systemError(const std::string& what, const std::string& path)
{
  return what + " " + path + ": " + std::strerror(errno);
}

/// Writes all of \p text to \p fd; false (errno set) on failure.
bool writeAll(int fd, const std::string& text)
{
  std::size_t done = 0;
  while (done < text.size())
  {
    const ssize_t written = ::write(fd, text.data() + done, text.size() - done);
    if (written < 0)
    {
      if (errno == EINTR)
      {
        continue;
      }
      return false;
    }
    done += static_cast<std::size_t>(written);
  }
  return true;
}

/// fsyncs directory \p directory, so a rename in it survives a power loss; false if it could not.
bool syncDirectory(const std::string& directory)
{
  const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0)
  {
    return false;
  }
  const bool synced = ::fsync(fd) == 0;
  ::close(fd);
  return synced;
}
}  // namespace

std::string writeFileAtomically(const std::string& path, const std::string& text)
{
  const fs::path target(path);
  const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code error;
  fs::create_directories(directory, error);
  if (error)
  {
    return "cannot create the directory " + directory.string() + ": " + error.message();
  }
  // The temporary file is in the target's directory, so the rename is atomic (same file system).
  std::string temporary = (directory / ("." + target.filename().string() + ".XXXXXX")).string();
  std::vector<char> name(temporary.begin(), temporary.end());
  name.push_back('\0');
  const int fd = ::mkostemp(name.data(), O_CLOEXEC);
  if (fd < 0)
  {
    return systemError("cannot create a temporary file in", directory.string());
  }
  temporary = name.data();
  std::string reason;
  if (::fchmod(fd, 0644) != 0 || !writeAll(fd, text))
  {
    reason = systemError("cannot write", temporary);
  }
  else if (::fsync(fd) != 0)
  {
    reason = systemError("cannot fsync", temporary);
  }
  if (::close(fd) != 0 && reason.empty())
  {
    reason = systemError("cannot close", temporary);
  }
  if (reason.empty() && ::rename(temporary.c_str(), path.c_str()) != 0)
  {
    reason = systemError("cannot rename " + temporary + " to", path);
  }
  if (!reason.empty())
  {
    ::unlink(temporary.c_str());
    return reason;
  }
  // The new file is in place whatever this says; a failed directory fsync only leaves the rename less durable, and
  // reporting it as a failed save would make the caller's view of the presets differ from the file's.
  syncDirectory(directory.string());
  return {};
}

std::string readStoredFile(const std::string& path, std::optional<std::string>& text)
{
  text.reset();
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (status.type() == fs::file_type::not_found)
  {
    return {};  // no file yet
  }
  if (error)
  {
    return "cannot read " + path + ": " + error.message();
  }
  if (status.type() != fs::file_type::regular)
  {
    return path + " is not a regular file";
  }
  std::ifstream file(path);
  std::stringstream content;
  content << file.rdbuf();
  if (!file)
  {
    return systemError("cannot read", path);
  }
  text = content.str();
  return {};
}

}  // namespace ptz_action_server
