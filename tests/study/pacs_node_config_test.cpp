// The PACS node editor's model (issue 41 item 8): each problem names its field, the node file
// is written whole (read back by JSON and by io/pacs' own loader) or not at all, secrets are
// never handed back, and keys this version does not know survive an edit.
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "pacs_node_config.h"
#include "voxray/io/error.h"

namespace voxray {
namespace {
namespace fs = std::filesystem;

PacsNodeForm dimse() {
  PacsNodeForm f;
  f.name = "hospital";
  f.calledAe = "ORTHANC";
  f.host = "127.0.0.1";
  f.port = "4242";
  return f;
}

PacsNodeForm web() {
  PacsNodeForm f;
  f.name = "cloud";
  f.web = true;
  f.baseUrl = "https://pacs.example/dicom-web/";
  f.auth = PacsNodeForm::Auth::Basic;
  f.user = "reader";
  f.password = "s3cret-pw";
  return f;
}

std::vector<std::string> fields(const std::vector<PacsFieldError>& errors) {
  std::vector<std::string> out;
  for (const auto& e : errors) out.push_back(e.field);
  return out;
}

fs::path freshFolder(const std::string& tag) {
  const fs::path d =
      fs::temp_directory_path() / ("voxray-pacs-node-" + tag + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

nlohmann::json readJson(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

TEST(PacsNodeForm, AValidDimseAndWebNodeHaveNoProblems) {
  EXPECT_TRUE(validatePacsNodeForm(dimse(), {}).empty());
  EXPECT_TRUE(validatePacsNodeForm(web(), {}).empty());
}

TEST(PacsNodeForm, PortOutsideOneTo65535IsNamedWithTheValue) {
  for (const char* port : {"0", "65536", "70000", "-1", "104x", ""}) {
    PacsNodeForm f = dimse();
    f.port = port;
    const auto errors = validatePacsNodeForm(f, {});
    ASSERT_EQ(fields(errors), std::vector<std::string>{"port"}) << port;
    EXPECT_EQ(errors[0].message, "Port: '" + std::string(port) +
                                     "' is not a whole number 1..65535 (the PACS's DICOM port, "
                                     "often 104 or 11112)");
  }
  PacsNodeForm f = dimse();
  f.port = "65535";
  EXPECT_TRUE(validatePacsNodeForm(f, {}).empty());
  f.port = "1";
  EXPECT_TRUE(validatePacsNodeForm(f, {}).empty());
}

TEST(PacsNodeForm, AeTitleIsOneTo16CharactersWithoutBackslashOrControlCharacters) {
  EXPECT_EQ(aeTitleProblem("ABCDEFGHIJKLMNOP"), "");  // 16
  EXPECT_EQ(aeTitleProblem("MY AE-1_x.+"), "");
  EXPECT_EQ(aeTitleProblem("ABCDEFGHIJKLMNOPQ"),
            "'ABCDEFGHIJKLMNOPQ' has 17 characters; an AE title has at most 16");
  EXPECT_EQ(aeTitleProblem(""), "is empty; give the AE title (1 to 16 characters)");
  EXPECT_EQ(aeTitleProblem("    "), "is only spaces; give a name");
  for (const std::string bad : {"A\\B", "A@B", "A\tB", "\xc3\xa9T"})
    EXPECT_NE(aeTitleProblem(bad).find("holds a character an AE title cannot"), std::string::npos)
        << bad;
  PacsNodeForm f = dimse();
  f.callingAe = "OUR\\AE";
  const auto errors = validatePacsNodeForm(f, {});
  ASSERT_EQ(fields(errors), std::vector<std::string>{"callingAe"});
  EXPECT_EQ(errors[0].message.rfind("Our AE title: 'OUR\\AE' holds a character", 0), 0u);
}

TEST(PacsNodeForm, UrlMustBeHttpOrHttpsAndIsNotEchoed) {
  PacsNodeForm f = web();
  f.baseUrl = "ftp://pacs.example/?token=abc123";
  auto errors = validatePacsNodeForm(f, {});
  ASSERT_EQ(fields(errors), std::vector<std::string>{"baseUrl"});
  EXPECT_EQ(errors[0].message,
            "Base URL: must start with http:// or https:// (e.g. https://pacs/dicom-web)");
  f.baseUrl = "https://reader:hunter2@pacs.example/dicom-web";
  errors = validatePacsNodeForm(f, {});
  ASSERT_EQ(fields(errors), std::vector<std::string>{"baseUrl"});
  EXPECT_EQ(errors[0].message.find("hunter2"), std::string::npos);
  EXPECT_EQ(errors[0].message,
            "Base URL: holds a user or password; give them in User and Password");
  f.baseUrl = "http:///dicom-web";
  EXPECT_EQ(fields(validatePacsNodeForm(f, {})), std::vector<std::string>{"baseUrl"});
}

TEST(PacsNodeForm, NameIsRequiredAndUnique) {
  PacsNodeForm f = dimse();
  f.name = "  ";
  EXPECT_EQ(fields(validatePacsNodeForm(f, {})), std::vector<std::string>{"name"});
  f.name = "hospital";
  const auto errors = validatePacsNodeForm(f, {"other", "hospital"});
  ASSERT_EQ(fields(errors), std::vector<std::string>{"name"});
  EXPECT_EQ(errors[0].message, "Name: another node is already called 'hospital'");
}

TEST(PacsNodeForm, BasicAuthNeedsAPasswordUnlessOneIsStored) {
  PacsNodeForm f = web();
  f.password.clear();
  EXPECT_EQ(fields(validatePacsNodeForm(f, {})), std::vector<std::string>{"password"});
  PacsNode stored = nodeOf(web());
  EXPECT_TRUE(validatePacsNodeForm(f, {}, &stored).empty());
  EXPECT_EQ(nodeOf(f, &stored).password, "s3cret-pw");  // kept, not typed again
  f.auth = PacsNodeForm::Auth::Bearer;
  EXPECT_EQ(fields(validatePacsNodeForm(f, {}, &stored)), std::vector<std::string>{"bearerToken"});
}

TEST(PacsNodeForm, FormOfAStoredNodeHoldsNoSecret) {
  PacsNode n = nodeOf(web());
  const PacsNodeForm f = formOf(n);
  EXPECT_EQ(f.password, "");
  EXPECT_EQ(f.user, "reader");
  EXPECT_EQ(f.auth, PacsNodeForm::Auth::Basic);
  EXPECT_EQ(f.baseUrl, "https://pacs.example/dicom-web");  // the trailing '/' dropped
  EXPECT_EQ(storedSecretNote(n), "a password is stored; type a new one to replace it");
  n.password.clear();
  n.bearerToken = "tok";
  EXPECT_EQ(formOf(n).bearerToken, "");
  EXPECT_EQ(storedSecretNote(n), "a token is stored; type a new one to replace it");
}

TEST(PacsNodeFile, PutWritesAFileTheClientReadsBackOwnerOnly) {
  const fs::path dir = freshFolder("put");
  const fs::path path = dir / "voxray" / "pacs-nodes.json";  // the folder is made
  PacsNodeFile file(path.string());
  EXPECT_TRUE(file.nodes().empty());
  file.put(dimse());
  file.put(web());
  const auto json = readJson(path);
  EXPECT_EQ(json["nodes"]["hospital"]["url"], "dicom://ORTHANC@127.0.0.1:4242");
  EXPECT_EQ(json["nodes"]["hospital"]["callingAe"], "VOXRAY");
  EXPECT_FALSE(json["nodes"]["hospital"].contains("receivePort"));  // C-GET
  EXPECT_EQ(json["nodes"]["cloud"]["url"], "https://pacs.example/dicom-web");
  EXPECT_EQ(json["nodes"]["cloud"]["user"], "reader");
  EXPECT_EQ(json["nodes"]["cloud"]["timeout"], 30);
  const auto nodes = loadPacsNodes(path.string());
  ASSERT_EQ(nodes.size(), 2u);
  const PacsNode& h = nodes[1].name == "hospital" ? nodes[1] : nodes[0];
  EXPECT_EQ(h.port, 4242);
  EXPECT_EQ(h.calledAe, "ORTHANC");
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);  // passwords inside
  // Only the file: no temporary left beside it.
  EXPECT_EQ(std::distance(fs::directory_iterator(path.parent_path()), fs::directory_iterator{}), 1);
}

TEST(PacsNodeFile, AnInvalidNodeWritesNothing) {
  const fs::path path = freshFolder("invalid") / "pacs-nodes.json";
  PacsNodeFile file(path.string());
  PacsNodeForm f = dimse();
  f.port = "70000";
  try {
    file.put(f);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Input);
    EXPECT_EQ(std::string(e.what()).rfind("Port: '70000'", 0), 0u) << e.what();
  }
  EXPECT_FALSE(fs::exists(path));
}

TEST(PacsNodeFile, EditKeepsTheStoredPasswordRenamesAndKeepsUnknownKeys) {
  const fs::path path = freshFolder("edit") / "pacs-nodes.json";
  {
    std::ofstream out(path);
    out << R"({"comment": "by hand", "nodes": {"cloud": {"url": "https://pacs.example/dw",
      "user": "reader", "password": "s3cret-pw", "x-note": "ward 3"}}})";
  }
  PacsNodeFile file(path.string());
  PacsNodeForm f = formOf(*file.find("cloud"));
  f.name = "cloud2";
  f.baseUrl = "https://pacs2.example/dw";
  file.put(f, "cloud");
  const auto json = readJson(path);
  EXPECT_EQ(json["comment"], "by hand");
  EXPECT_FALSE(json["nodes"].contains("cloud"));
  EXPECT_EQ(json["nodes"]["cloud2"]["password"], "s3cret-pw");
  EXPECT_EQ(json["nodes"]["cloud2"]["x-note"], "ward 3");
  EXPECT_EQ(json["nodes"]["cloud2"]["url"], "https://pacs2.example/dw");
  // Switching to no authentication drops the stored user and password.
  f = formOf(*file.find("cloud2"));
  f.auth = PacsNodeForm::Auth::None;
  file.put(f, "cloud2");
  EXPECT_FALSE(readJson(path)["nodes"]["cloud2"].contains("password"));
  EXPECT_TRUE(file.remove("cloud2"));
  EXPECT_FALSE(file.remove("cloud2"));
  EXPECT_TRUE(readJson(path)["nodes"].empty());
}

TEST(PacsNodeFile, ABrokenFileIsRefusedAndLeftAlone) {
  const fs::path path = freshFolder("broken") / "pacs-nodes.json";
  {
    std::ofstream out(path);
    out << "{\"nodes\": {\"a\": ";
  }
  EXPECT_THROW(PacsNodeFile{path.string()}, Error);
  std::ifstream in(path);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "{\"nodes\": {\"a\": ");
}

}  // namespace
}  // namespace voxray
