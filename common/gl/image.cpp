#include "gl/image.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <stb_image.h>
#include <stb_image_write.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <optional>
#include <random>
#include <stdexcept>
#include <utility>

#include "gl/errors.h"

namespace stencil {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void refuse(const std::string& flag, const fs::path& path, const std::string& why) {
  throw OutputError(flag + " " + path.string() + ": " + why);
}

// Whether a new file can be made in the existing folder `dir`: one is made and removed again.
// Returns the system's reason when not, else an empty string.
std::string cannotCreateIn(const fs::path& dir) {
  const fs::path probe = dir / (".stencil-probe-" + std::to_string(getpid()));
  const int fd = open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0) return std::strerror(errno);
  close(fd);
  unlink(probe.c_str());
  return {};
}

// `dir` is a folder that exists and takes new files, or can be made: the nearest thing above it
// that exists is such a folder.
void checkFolderCanHoldFiles(const fs::path& dir, const std::string& flag, const fs::path& path) {
  fs::path existing = dir.empty() ? fs::path(".") : dir;
  for (;;) {
    std::error_code ec;
    const fs::file_status status = fs::status(existing, ec);
    if (status.type() != fs::file_type::not_found) {
      if (ec) refuse(flag, path, existing.string() + ": " + ec.message());
      if (!fs::is_directory(status)) refuse(flag, path, existing.string() + " is not a folder");
      break;
    }
    const fs::path up = existing.parent_path();
    if (up.empty() || up == existing) {
      if (existing == ".") refuse(flag, path, "the current folder does not exist");
      existing = ".";
    } else {
      existing = up;
    }
  }
  const std::string why = cannotCreateIn(existing);
  if (!why.empty()) refuse(flag, path, "cannot create files in " + existing.string() + ": " + why);
}

// Each name in the path within NAME_MAX bytes and the whole within PATH_MAX: what the system
// refuses when the file is made, refused before anything is rendered.
void checkNameLengths(const fs::path& path, const std::string& flag) {
  for (const fs::path& part : path)
    if (part.native().size() > NAME_MAX)
      refuse(flag, path, "the name '" + part.native().substr(0, 24) + "...' is " +
                             std::to_string(part.native().size()) + " bytes; a file name has at most " +
                             std::to_string(NAME_MAX));
  if (fs::absolute(path).native().size() >= PATH_MAX)
    refuse(flag, path, "the path is " + std::to_string(fs::absolute(path).native().size()) +
                           " bytes from the root; at most " + std::to_string(PATH_MAX - 1));
}

[[noreturn]] void cannotWrite(const fs::path& path, const std::string& why) {
  throw OutputError("could not write " + path.string() + ": " + why);
}

}  // namespace

namespace {

// A random name for a file beside the one being written: a dot file, short whatever the
// target's name, so a name the up-front check passed never fails here for its length.
std::string randomSiblingName() {
  static std::random_device device;
  static const char hex[] = "0123456789abcdef";
  std::string name = ".stencil-";
  for (int i = 0; i < 16; ++i) name += hex[device() & 15];
  return name + ".tmp";
}

// One staged file while a commit writes it: its descriptor, with no name until `linked`.
struct Writing {
  fs::path target, linked;  // linked: the random sibling name it has been given, once it has one
  int fd = -1;
  bool renamed = false;
};

// Where a file goes: as named when its folder exists (the system resolves "." and ".." there);
// else its folder written with "." or ".." (nd/./, nd/x/..) as it reads once those are resolved
// in the name, since nothing that does not exist yet can be a link for ".." to go back through.
fs::path whereItGoes(const fs::path& file) {
  std::error_code ec;
  if (!file.has_parent_path() || fs::is_directory(file.parent_path(), ec)) return file;
  fs::path folder = file.parent_path().lexically_normal();
  if (!folder.empty() && !folder.has_filename()) folder = folder.parent_path();  // "nd/" is "nd"
  return folder / file.filename();
}

// Makes the folders missing above and at `dir`, outermost first, recording each one made.
void makeFolders(const fs::path& dir, const fs::path& forFile, std::vector<fs::path>& made) {
  if (dir.empty() || dir == ".") return;
  std::vector<fs::path> missing;
  for (fs::path d = dir; !d.empty(); d = d.parent_path()) {
    std::error_code ec;
    if (fs::exists(fs::symlink_status(d, ec)) || d == d.root_path()) break;
    missing.push_back(d);
    if (d.parent_path() == d) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (mkdir(it->c_str(), 0777) != 0) {
      std::error_code ec;
      if (errno == EEXIST && fs::is_directory(*it, ec)) continue;  // made meanwhile, or ".." of one made
      cannotWrite(forFile, it->string() + ": " + std::strerror(errno));
    }
    made.push_back(*it);
  }
}

// Opens a file with no name in `dir` (O_TMPFILE). Where the file system cannot, a new file at a
// random name that no link may stand at (O_EXCL), recorded in `linked` for removal.
int openUnnamed(const fs::path& dir, fs::path& linked) {
  const fs::path folder = dir.empty() ? fs::path(".") : dir;
  int fd = open(folder.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
  if (fd >= 0 || (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL)) return fd;
  for (int attempt = 0; attempt < 16; ++attempt) {
    const fs::path name = folder / randomSiblingName();
    fd = open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd >= 0) {
      linked = name;
      return fd;
    }
    if (errno != EEXIST) return -1;
  }
  return -1;
}

bool writeAll(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      return false;
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

// Gives an unnamed file (O_TMPFILE) a random name beside its target: linkat never replaces an
// existing name, so a name someone planted is skipped, never followed.
bool giveName(Writing& w) {
  const std::string self = "/proc/self/fd/" + std::to_string(w.fd);
  const fs::path folder = w.target.has_parent_path() ? w.target.parent_path() : fs::path(".");
  for (int attempt = 0; attempt < 16; ++attempt) {
    const fs::path name = folder / randomSiblingName();
    if (linkat(AT_FDCWD, self.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) == 0) {
      w.linked = name;
      return true;
    }
    if (errno != EEXIST) return false;
  }
  return false;
}

// Holds off SIGINT, SIGTERM and SIGHUP while it lives: a handler (process-wide, so whichever thread
// the signal reaches, the GL driver's included) notes the signal, and the destructor puts the
// old actions back and raises it, so that it does what it would have done, once the set is named.
volatile std::sig_atomic_t heldSignal = 0;
extern "C" void noteSignal(int sig) {
  heldSignal = sig;
}
class SignalsHeld {
 public:
  SignalsHeld() {
    struct sigaction hold {};
    hold.sa_handler = noteSignal;
    sigemptyset(&hold.sa_mask);
    for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &hold, &old_[i]);
  }
  ~SignalsHeld() {
    for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &old_[i], nullptr);
    const int sig = heldSignal;
    heldSignal = 0;
    if (sig != 0) std::raise(sig);
  }
  SignalsHeld(const SignalsHeld&) = delete;
  SignalsHeld& operator=(const SignalsHeld&) = delete;

 private:
  static constexpr std::array<int, 3> kSignals{SIGINT, SIGTERM, SIGHUP};
  std::array<struct sigaction, 3> old_{};
};

// Room for `count` more open files: the soft limit raised towards the hard one where needed.
void makeRoomForFiles(std::size_t count) {
  rlimit limit{};
  if (getrlimit(RLIMIT_NOFILE, &limit) != 0) return;
  const rlim_t wanted = static_cast<rlim_t>(count) + 64;
  if (limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur < wanted) {
    limit.rlim_cur = limit.rlim_max == RLIM_INFINITY ? wanted : std::min(wanted, limit.rlim_max);
    setrlimit(RLIMIT_NOFILE, &limit);
  }
}

}  // namespace

void OutputSet::add(const fs::path& path, std::string bytes) {
  for (Staged& f : files_)
    if (f.path == path) {
      f.bytes = std::move(bytes);
      return;
    }
  files_.push_back({path, std::move(bytes)});
}

std::string encodePng(const Image& image) {
  std::string png;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &png, image.width, image.height, image.channels, image.pixels.data(),
                              image.width * image.channels))
    throw OutputError("could not encode a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                      " image as PNG");
  return png;
}

void OutputSet::addPng(const fs::path& path, const Image& image) {
  std::string png;
  try {
    png = encodePng(image);
  } catch (const OutputError&) {
    throw OutputError("could not encode " + path.string() + " as PNG");
  }
  add(path, std::move(png));
}

void OutputSet::commit() {
  std::vector<Staged> files = std::move(files_);
  files_.clear();
  std::vector<fs::path> folders;  // made by this commit, outermost first
  std::vector<Writing> writing;
  const auto undo = [&] {
    for (Writing& w : writing) {
      if (w.fd >= 0) close(w.fd);
      if (!w.linked.empty() && !w.renamed) unlink(w.linked.c_str());
      if (w.renamed) unlink(w.target.c_str());
    }
    for (auto it = folders.rbegin(); it != folders.rend(); ++it) rmdir(it->c_str());
  };
  std::optional<SignalsHeld> held;  // from the first name given until the undo, if any, is done
  try {
    makeRoomForFiles(files.size());
    for (const Staged& f : files) {
      if (f.path.empty()) throw OutputError("could not write a file with an empty name");
      const fs::path target = whereItGoes(f.path);
      makeFolders(target.parent_path(), f.path, folders);
      Writing& w = writing.emplace_back();
      w.target = target;
      w.fd = openUnnamed(target.parent_path(), w.linked);
      if (w.fd < 0 || !writeAll(w.fd, f.bytes)) cannotWrite(f.path, std::strerror(errno));
    }
    held.emplace();
    for (Writing& w : writing)
      if (w.linked.empty() && !giveName(w)) cannotWrite(w.target, std::strerror(errno));
    for (Writing& w : writing) {
      if (std::rename(w.linked.c_str(), w.target.c_str()) != 0) cannotWrite(w.target, std::strerror(errno));
      w.renamed = true;
    }
    for (Writing& w : writing) close(std::exchange(w.fd, -1));
  } catch (...) {
    undo();
    throw;
  }
}

void writeFile(const fs::path& path, std::string_view bytes) {
  OutputSet set;
  set.add(path, std::string(bytes));
  set.commit();
}

void writePng(const fs::path& path, const Image& image) {
  OutputSet set;
  set.addPng(path, image);
  set.commit();
}

Image readPng(const fs::path& path, int channels) {
  int w = 0, h = 0, fileChannels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &fileChannels, channels);
  if (!data) throw std::runtime_error("could not read " + path.string() + ": " + stbi_failure_reason());
  Image image(w, h, channels);
  std::copy(data, data + image.pixels.size(), image.pixels.begin());
  stbi_image_free(data);
  return image;
}

void checkOutputFile(const fs::path& path, const std::string& flag) {
  if (path.empty()) throw OutputError(flag + ": the file name is empty");
  checkNameLengths(path, flag);
  if (!path.has_filename()) refuse(flag, path, "names a folder; a file name is expected");
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::is_directory(status)) refuse(flag, path, "is a folder; a file name is expected");
  if (fs::exists(status) && !fs::is_regular_file(status))
    refuse(flag, path, "is not a regular file; files are written beside their name and renamed onto it");
  checkFolderCanHoldFiles(path.parent_path(), flag, path);
}

void checkOutputFolder(const fs::path& path, const std::string& flag) {
  if (path.empty()) throw OutputError(flag + ": the folder name is empty");
  checkNameLengths(path, flag);
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::exists(status) && !fs::is_directory(status)) refuse(flag, path, "is not a folder");
  checkFolderCanHoldFiles(path, flag, path);
}

}  // namespace stencil
