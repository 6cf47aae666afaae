#pragma once
// The PACS node editor's work (File > Open from PACS… > Nodes…), Qt-free: a node as the
// editor's fields hold it (text, as typed), its validation with messages naming the field,
// and the node file (pacsConfigPath(), io/pacs) read and written whole: a temporary beside
// it, then a rename, so a crash never leaves half a file. Secrets (password, token) are
// never handed back to be shown: an edited node keeps its stored secret unless a new one is
// typed, and nothing here logs.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "no_qt.h"

#ifdef VOXRAY_HAS_DICOM
#include "voxray/io/pacs.h"

namespace voxray {

struct PacsNodeForm {
  enum class Auth { None, Basic, Bearer };
  std::string name;
  bool web = false;  // false: DIMSE
  // DIMSE: the node's AE title, host and port; ours (the calling AE); C-MOVE's receive port
  // ("" or "0": C-GET).
  std::string calledAe, host, port = "104", callingAe = "VOXRAY", receivePort;
  // DICOMweb
  std::string baseUrl;
  Auth auth = Auth::None;
  std::string user, password, bearerToken;  // an empty secret on an edit keeps the stored one
  std::string caFile;
  std::string timeout = "30";  // seconds
};

struct PacsFieldError {
  std::string field;    // the form's field: "name", "calledAe", "host", "port", "callingAe",
                        // "receivePort", "baseUrl", "user", "password", "bearerToken", "timeout"
  std::string message;  // starts with the field's label as the editor shows it
};

// The field's label in the editor ("Port", "Called AE title", ...).
std::string pacsFieldLabel(const std::string& field);

// An AE title's problem ("" when valid): 1..16 characters of DICOM's default repertoire
// without backslash or control characters (PS3.5 AE), not only spaces, and no '@' (the node
// file keeps dicom://AE@host:port).
std::string aeTitleProblem(const std::string& ae);

// Every problem of the form, in the editor's order. OTHERNAMES: the other nodes' names (a
// name must be unique). STORED: the node being edited (its secrets count as given), or null.
std::vector<PacsFieldError> validatePacsNodeForm(const PacsNodeForm& form,
                                                 const std::vector<std::string>& otherNames,
                                                 const PacsNode* stored = nullptr);

// The form of a stored node, its secrets left out (formSecretStored says which is stored).
PacsNodeForm formOf(const PacsNode& node);
// "a password is stored" / "a token is stored" / "": what the editor shows instead of it.
std::string storedSecretNote(const PacsNode& node);

// The node a valid form describes (Test echoes it), with STORED's secrets where the form
// gives none. Throws Input with the first problem.
PacsNode nodeOf(const PacsNodeForm& form, const PacsNode* stored = nullptr);

class PacsNodeFile {
 public:
  // Reads PATH (a missing file: no nodes). Throws Input when it is not a node file: the
  // editor then refuses to overwrite it.
  explicit PacsNodeFile(std::string path = pacsConfigPath());

  const std::string& path() const { return path_; }
  const std::vector<PacsNode>& nodes() const { return nodes_; }
  const PacsNode* find(const std::string& name) const;

  // Adds the node (ORIGINALNAME empty) or replaces ORIGINALNAME's (renamed when the form's
  // name differs), then writes the file. Throws Input naming the field when the form is
  // not valid; nothing is written then.
  void put(const PacsNodeForm& form, const std::string& originalName = "");
  // Removes NAME and writes the file; false when there is no such node.
  bool remove(const std::string& name);

 private:
  void write();  // temporary beside the file, owner-only (it holds secrets), then rename
  std::string path_;
  nlohmann::json json_;  // the whole file: keys this version does not know are kept
  std::vector<PacsNode> nodes_;
};

}  // namespace voxray
#endif
