// The one error type of Cooperage (STYLE rule 5): a code, the entity it is
// about, and a sentence for a person.
#pragma once

#include <stdexcept>
#include <string>

namespace cooperage {

enum class ErrorCode {
  InvalidInput,   ///< bad argument or setting (negative size, unknown id)
  FileNotFound,   ///< an input file does not exist or cannot be read
  ParseError,     ///< malformed journal or CAD file
  GeometryError,  ///< the CAD kernel failed (boolean, import, healing)
  NotSupported,   ///< parsed, but the behaviour lands in a later release
  NotApplicable,  ///< no scheme can mesh the entity
  Infeasible,     ///< interval constraints cannot be satisfied
  MeshingFailed,  ///< a scheme failed on an entity it accepted
  Internal,       ///< a broken invariant: a bug in Cooperage
};

/// Printable name of an error code ("parse error", ...).
const char* to_string(ErrorCode code);

/// What an error is about: a geometric entity of dimension 0..3 with its
/// 1-based id, or nothing (dim = -1).
struct EntityRef {
  int dim = -1;
  int id = 0;
  static EntityRef none() { return {}; }
  static EntityRef vertex(int id) { return {0, id}; }
  static EntityRef curve(int id) { return {1, id}; }
  static EntityRef surface(int id) { return {2, id}; }
  static EntityRef volume(int id) { return {3, id}; }
  /// "surface 12", or "" for none.
  std::string name() const;
};

/// Thrown at module boundaries (I/O, OCCT, journal) and by schemes.
/// what() is the full one-line message: "<entity>: <message>".
class MeshingError : public std::runtime_error {
 public:
  MeshingError(ErrorCode code, EntityRef entity, const std::string& message);
  MeshingError(ErrorCode code, const std::string& message)
      : MeshingError(code, EntityRef::none(), message) {}
  /// With a hint: what the person can do about it ("use a larger size").
  MeshingError(ErrorCode code, EntityRef entity, const std::string& message,
               const std::string& hint)
      : MeshingError(code, entity, message) {
    hint_ = hint;
  }

  ErrorCode code() const { return code_; }
  const EntityRef& entity() const { return entity_; }
  /// The message without the entity prefix.
  const std::string& message() const { return message_; }
  /// What to do about it, one sentence, or "" (not part of what()).
  const std::string& hint() const { return hint_; }

 private:
  ErrorCode code_;
  EntityRef entity_;
  std::string message_;
  std::string hint_;
};

}  // namespace cooperage
