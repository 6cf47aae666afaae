#include "pacs_node_config.h"

#ifdef VOXRAY_HAS_DICOM
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "voxray/io/error.h"
#include "voxray/io/temporary_file.h"

namespace voxray {
namespace fs = std::filesystem;

namespace {

bool startsWith(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

std::string trimmed(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

// A whole number in [LO, HI], or the problem ("" when fine).
std::string numberProblem(const std::string& text, long lo, long hi, long& value) {
  const std::string t = trimmed(text);
  char* end = nullptr;
  value = std::strtol(t.c_str(), &end, 10);
  if (t.empty() || *end != '\0' || value < lo || value > hi)
    return "'" + t + "' is not a whole number " + std::to_string(lo) + ".." + std::to_string(hi);
  return "";
}

void add(std::vector<PacsFieldError>& errors, const std::string& field, const std::string& what) {
  errors.push_back({field, pacsFieldLabel(field) + ": " + what});
}

}  // namespace

std::string pacsFieldLabel(const std::string& field) {
  static const std::pair<const char*, const char*> labels[] = {
      {"name", "Name"},
      {"calledAe", "Called AE title"},
      {"host", "Host"},
      {"port", "Port"},
      {"callingAe", "Our AE title"},
      {"receivePort", "Receive port (C-MOVE)"},
      {"baseUrl", "Base URL"},
      {"user", "User"},
      {"password", "Password"},
      {"bearerToken", "Token"},
      {"caFile", "CA file"},
      {"timeout", "Timeout"}};
  for (const auto& [key, label] : labels)
    if (field == key) return label;
  return field;
}

std::string aeTitleProblem(const std::string& ae) {
  if (ae.empty()) return "is empty; give the AE title (1 to 16 characters)";
  if (ae.size() > 16)
    return "'" + ae + "' has " + std::to_string(ae.size()) +
           " characters; an AE title has at most 16";
  if (ae.find_first_not_of(' ') == std::string::npos) return "is only spaces; give a name";
  for (unsigned char c : ae) {
    if (c < 0x20 || c > 0x7e || c == '\\' || c == '@')
      return "'" + ae +
             "' holds a character an AE title cannot (letters, digits, spaces and printable "
             "ASCII except \\ and @)";
  }
  return "";
}

std::vector<PacsFieldError> validatePacsNodeForm(const PacsNodeForm& f,
                                                 const std::vector<std::string>& otherNames,
                                                 const PacsNode* stored) {
  std::vector<PacsFieldError> errors;
  const std::string name = trimmed(f.name);
  if (name.empty())
    add(errors, "name", "is empty; give the node a name (PACS dialogs list it by this name)");
  else if (name.find("://") != std::string::npos)
    add(errors, "name", "'" + name + "' looks like an address; give a short name");
  else if (std::find(otherNames.begin(), otherNames.end(), name) != otherNames.end())
    add(errors, "name", "another node is already called '" + name + "'");
  long value = 0;
  if (!f.web) {
    if (auto p = aeTitleProblem(f.calledAe); !p.empty()) add(errors, "calledAe", p);
    const std::string host = trimmed(f.host);
    if (host.empty())
      add(errors, "host", "is empty; give the PACS's host name or IP address");
    else if (host.find_first_of(" /@\\") != std::string::npos)
      add(errors, "host", "'" + host + "' is not a host name or IP address");
    if (auto p = numberProblem(f.port, 1, 65535, value); !p.empty())
      add(errors, "port", p + " (the PACS's DICOM port, often 104 or 11112)");
    if (auto p = aeTitleProblem(f.callingAe); !p.empty()) add(errors, "callingAe", p);
    if (!trimmed(f.receivePort).empty())
      if (auto p = numberProblem(f.receivePort, 0, 65535, value); !p.empty())
        add(errors, "receivePort", p + " (0 or empty: retrieve with C-GET)");
  } else {
    const std::string url = trimmed(f.baseUrl);
    if (!startsWith(url, "http://") && !startsWith(url, "https://")) {
      // Not echoed: a mistyped URL may still hold a token.
      add(errors, "baseUrl", "must start with http:// or https:// (e.g. https://pacs/dicom-web)");
    } else {
      const std::string rest = url.substr(url.find("://") + 3);
      const std::string authority = rest.substr(0, rest.find('/'));
      if (authority.find('@') != std::string::npos)
        add(errors, "baseUrl", "holds a user or password; give them in User and Password");
      else if (authority.empty())
        add(errors, "baseUrl", "has no host");
    }
    if (f.auth == PacsNodeForm::Auth::Basic) {
      if (trimmed(f.user).empty()) add(errors, "user", "is empty; basic authentication needs one");
      if (f.password.empty() && !(stored && !stored->password.empty()))
        add(errors, "password", "is empty; basic authentication needs one");
    }
    if (f.auth == PacsNodeForm::Auth::Bearer && f.bearerToken.empty() &&
        !(stored && !stored->bearerToken.empty()))
      add(errors, "bearerToken", "is empty; bearer authentication needs one");
  }
  if (auto p = numberProblem(f.timeout, 1, 3600, value); !p.empty())
    add(errors, "timeout", p + " seconds");
  return errors;
}

PacsNodeForm formOf(const PacsNode& n) {
  PacsNodeForm f;
  f.name = n.name;
  f.web = n.transport == PacsNode::Transport::Web;
  f.calledAe = n.calledAe;
  f.host = n.host;
  f.port = std::to_string(n.port);
  f.callingAe = n.callingAe;
  f.receivePort = n.receivePort > 0 ? std::to_string(n.receivePort) : "";
  f.baseUrl = n.baseUrl;
  f.auth = !n.bearerToken.empty()                   ? PacsNodeForm::Auth::Bearer
           : !n.user.empty() || !n.password.empty() ? PacsNodeForm::Auth::Basic
                                                    : PacsNodeForm::Auth::None;
  f.user = n.user;
  f.caFile = n.caFile;
  f.timeout = std::to_string(n.timeoutSec);
  return f;  // no password, no token
}

std::string storedSecretNote(const PacsNode& n) {
  if (!n.bearerToken.empty()) return "a token is stored; type a new one to replace it";
  if (!n.password.empty()) return "a password is stored; type a new one to replace it";
  return "";
}

PacsNode nodeOf(const PacsNodeForm& f, const PacsNode* stored) {
  // The name is checked by put(); a node tested before it is saved needs none.
  PacsNodeForm named = f;
  if (trimmed(named.name).empty()) named.name = "unsaved";
  const auto errors = validatePacsNodeForm(named, {}, stored);
  if (!errors.empty()) throw inputError(errors.front().message);
  PacsNode n;
  n.name = trimmed(f.name);
  n.timeoutSec = std::atoi(trimmed(f.timeout).c_str());
  n.caFile = trimmed(f.caFile);
  if (!f.web) {
    n.transport = PacsNode::Transport::Dimse;
    n.calledAe = f.calledAe;
    n.host = trimmed(f.host);
    n.port = std::atoi(trimmed(f.port).c_str());
    n.callingAe = f.callingAe;
    n.receivePort = std::atoi(trimmed(f.receivePort).c_str());
    return n;
  }
  n.transport = PacsNode::Transport::Web;
  n.baseUrl = trimmed(f.baseUrl);
  while (!n.baseUrl.empty() && n.baseUrl.back() == '/') n.baseUrl.pop_back();
  if (f.auth == PacsNodeForm::Auth::Basic) {
    n.user = trimmed(f.user);
    n.password = !f.password.empty() ? f.password : stored ? stored->password : "";
  } else if (f.auth == PacsNodeForm::Auth::Bearer) {
    n.bearerToken = !f.bearerToken.empty() ? f.bearerToken : stored ? stored->bearerToken : "";
  }
  return n;
}

PacsNodeFile::PacsNodeFile(std::string path) : path_(std::move(path)) {
  nodes_ = loadPacsNodes(path_);  // throws Input on a broken file, naming it
  std::ifstream in(path_);
  json_ = in ? nlohmann::json::parse(in) : nlohmann::json::object();
  if (!json_.contains("nodes")) json_["nodes"] = nlohmann::json::object();
}

const PacsNode* PacsNodeFile::find(const std::string& name) const {
  for (const auto& n : nodes_)
    if (n.name == name) return &n;
  return nullptr;
}

void PacsNodeFile::put(const PacsNodeForm& form, const std::string& originalName) {
  const PacsNode* stored = originalName.empty() ? nullptr : find(originalName);
  std::vector<std::string> others;
  for (const auto& n : nodes_)
    if (n.name != originalName) others.push_back(n.name);
  const auto errors = validatePacsNodeForm(form, others, stored);
  if (!errors.empty()) throw inputError(errors.front().message);
  const PacsNode n = nodeOf(form, stored);
  nlohmann::json& all = json_["nodes"];
  nlohmann::json entry = stored ? all[originalName] : nlohmann::json::object();
  for (const char* key :
       {"url", "callingAe", "receivePort", "user", "password", "bearerToken", "caFile", "timeout"})
    entry.erase(key);
  if (n.transport == PacsNode::Transport::Dimse) {
    entry["url"] = "dicom://" + n.calledAe + "@" + n.host + ":" + std::to_string(n.port);
    entry["callingAe"] = n.callingAe;
    if (n.receivePort > 0) entry["receivePort"] = n.receivePort;
  } else {
    entry["url"] = n.baseUrl;
    if (!n.user.empty()) entry["user"] = n.user;
    if (!n.password.empty()) entry["password"] = n.password;
    if (!n.bearerToken.empty()) entry["bearerToken"] = n.bearerToken;
  }
  if (!n.caFile.empty()) entry["caFile"] = n.caFile;
  entry["timeout"] = n.timeoutSec;
  if (!originalName.empty()) all.erase(originalName);
  all[n.name] = entry;
  write();
}

bool PacsNodeFile::remove(const std::string& name) {
  if (!find(name)) return false;
  json_["nodes"].erase(name);
  write();
  return true;
}

void PacsNodeFile::write() {
  const fs::path target(path_);
  std::error_code ec;
  if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
  const fs::path temporary = temporaryBeside(target);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << json_.dump(2) << "\n";
    out.close();
    if (!out) {
      fs::remove(temporary, ec);
      throw outputError("cannot write the PACS node file " + path_ +
                        ": check that its folder exists and is writable");
    }
  }
  // It may hold passwords and tokens: readable by its owner only.
  ::chmod(temporary.c_str(), S_IRUSR | S_IWUSR);
  fs::rename(temporary, target, ec);
  if (ec) {
    fs::remove(temporary, ec);
    throw outputError("cannot replace the PACS node file " + path_ + " (" + ec.message() + ")");
  }
  nodes_ = loadPacsNodes(path_);
}

}  // namespace voxray
#endif
