#include "framework/io/export/write_mesh.h"

#include "framework/core/error.h"
#include "framework/core/text.h"
#include "framework/io/export/exodus_writer.h"
#include "framework/io/export/export_common.h"
#include "framework/io/export/inp_writer.h"
#include "framework/io/export/msh_writer.h"
#include "framework/io/export/surface_writer.h"
#include "framework/io/export/vtu_writer.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <climits>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace cooperage::io {
namespace {

namespace fs = std::filesystem;

std::string extension_of(const std::string& path) {
  const size_t slash = path.find_last_of("/\\");
  const size_t dot = path.find_last_of('.');
  std::string ext;
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) {
    ext = path.substr(dot + 1);
  }
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::string directory_of(const std::string& path) {
  const fs::path dir = fs::path(path).parent_path();
  return dir.empty() ? std::string(".") : dir.string();
}

/// mkdtemp in `dir`: a new directory only we can enter; "" on failure
/// (errno set).
std::string make_private_dir(const std::string& dir) {
  std::string templ = (fs::path(dir) / ".cooperage-XXXXXX").string();
  if (!::mkdtemp(templ.data())) return {};
  return templ;
}

void remove_dir_tree(const std::string& dir) noexcept {
  std::error_code ec;
  fs::remove_all(dir, ec);
}

}  // namespace

void prepare_export(const std::string& path) noexcept {
  const std::string ext = extension_of(path);
  if (ext != "exo" && ext != "e" && ext != "g") return;
  try {
    load_exodus_library();
  } catch (...) {  // the write will say why
  }
}

bool known_mesh_extension(const std::string& path) {
  const std::string ext = extension_of(path);
  return ext == "exo" || ext == "e" || ext == "g" || ext == "msh" || ext == "vtu" || ext == "inp" ||
         is_surface_format(ext);
}

void write_mesh(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
                const ExportOptions& options) {
  const std::string ext = extension_of(path);
  if (ext == "exo" || ext == "e" || ext == "g") return write_exodus(path, db, model, options);
  if (ext == "msh") return write_msh(path, db, model, options);
  if (ext == "vtu") return write_vtu(path, db, model, options);
  if (ext == "inp") return write_inp(path, db, model, options);
  if (is_surface_format(ext)) return write_surface_mesh(path, db, model, options);
  throw MeshingError(ErrorCode::InvalidInput,
                     "cannot export '" + clip_path(path) + "': unknown extension '" +
                         (ext.empty() ? std::string() : "." + clip(ext, 16)) +
                         "' (allowed: .exo, .e, .g (Exodus II), .msh (Gmsh 4.1), "
                         ".vtu (VTK), .inp (Abaqus), .obj, .off, .stl, .ply (surfaces))");
}

void check_export_target(const std::string& path) {
  if (path.empty()) throw MeshingError(ErrorCode::InvalidInput, "the file name is empty");
  if (!known_mesh_extension(path))
    throw MeshingError(ErrorCode::InvalidInput,
                       "\"" + clip_path(path) +
                           "\" has no mesh file extension (allowed: .exo, "
                           ".e, .g, .msh, .vtu, .inp, .obj, .off, .stl, .ply)");
  const std::string name = fs::path(path).filename().string();
  if (name.size() > NAME_MAX || path.size() >= PATH_MAX)
    throw MeshingError(ErrorCode::InvalidInput,
                       "\"" + clip_path(path) + "\": the file name is too long (" +
                           std::to_string(name.size()) + " characters, at most " +
                           std::to_string(NAME_MAX) + ")");
  const std::string dir = directory_of(path);
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0)
    throw MeshingError(ErrorCode::FileNotFound,
                       "the directory \"" + clip_path(dir) + "\" does not exist");
  if (!S_ISDIR(st.st_mode))
    throw MeshingError(ErrorCode::FileNotFound, "\"" + clip_path(dir) + "\" is not a directory");
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw MeshingError(ErrorCode::FileNotFound, "\"" + clip_path(path) + "\" is a directory");
  const std::string probe = make_private_dir(dir);
  if (probe.empty()) {
    const int err = errno;
    throw MeshingError(ErrorCode::FileNotFound, "cannot create files in \"" + clip_path(dir) +
                                                    "\" (" + std::strerror(err) + ")");
  }
  ::rmdir(probe.c_str());
}

ExportBatch::~ExportBatch() { discard(); }

void ExportBatch::discard() noexcept {
  for (const Staged& s : staged_) remove_dir_tree(s.dir);
  staged_.clear();
}

void ExportBatch::stage(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
                        const ExportOptions& options) {
  if (!known_mesh_extension(path)) write_mesh(path, db, model, options);  // throws the message
  const std::string dir = make_private_dir(directory_of(path));
  if (dir.empty()) {
    const int err = errno;
    discard();
    throw MeshingError(ErrorCode::FileNotFound,
                       "cannot write '" + clip_path(path) + "' (" + std::strerror(err) + ")");
  }
  // A short name inside the private directory; when even that path is long,
  // the writers get it through /proc/self/fd (libexodus aborts on an error
  // with a path of more than ~250 characters).
  const std::string leaf = "mesh." + extension_of(path);
  const std::string file = (fs::path(dir) / leaf).string();
  int dir_fd = -1;
  std::string writer_path = file;
  if (file.size() > 200) {
    dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    const std::string short_path = "/proc/self/fd/" + std::to_string(dir_fd) + "/" + leaf;
    struct stat st {};
    if (dir_fd >= 0 && ::stat(("/proc/self/fd/" + std::to_string(dir_fd)).c_str(), &st) == 0)
      writer_path = short_path;
  }
  try {
    write_mesh(writer_path, db, model, options);
  } catch (const MeshingError& e) {
    if (dir_fd >= 0) ::close(dir_fd);
    remove_dir_tree(dir);
    discard();
    if (writer_path == file) throw;
    throw MeshingError(e.code(), e.entity(), "cannot write '" + clip_path(path) + "'", e.hint());
  } catch (...) {
    if (dir_fd >= 0) ::close(dir_fd);
    remove_dir_tree(dir);
    discard();
    throw;
  }
  if (dir_fd >= 0) ::close(dir_fd);
  staged_.push_back({path, dir, file});
}

std::vector<std::string> ExportBatch::commit() {
  std::vector<std::string> done;
  for (const Staged& s : staged_) {
    if (const int err = detail::replace_file(s.file, s.target); err != 0) {
      for (const std::string& t : done) ::unlink(t.c_str());
      const std::string target = s.target;
      discard();
      throw MeshingError(ErrorCode::FileNotFound,
                         "cannot write '" + clip_path(target) + "' (" + std::strerror(err) + ")");
    }
    done.push_back(s.target);
  }
  discard();  // the private directories, now empty
  return done;
}

}  // namespace cooperage::io
