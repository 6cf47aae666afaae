#include "import_journal.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "voxray/io/error.h"

namespace voxray::studydb {
namespace {

using nlohmann::json;

json instanceJson(const InstanceFields& i) {
  return {{"path", i.path},         {"sop", i.sopInstanceUid},
          {"class", i.sopClassUid}, {"ts", i.transferSyntaxUid},
          {"pos", i.position},      {"n", i.number},
          {"frames", i.frames},     {"size", i.size},
          {"mtime", i.mtime},       {"stored", i.stored}};
}

InstanceFields instanceFrom(const json& j) {
  InstanceFields i;
  i.path = j.at("path").get<std::string>();
  i.sopInstanceUid = j.at("sop").get<std::string>();
  i.sopClassUid = j.value("class", "");
  i.transferSyntaxUid = j.value("ts", "");
  i.position = j.value("pos", "");
  i.number = j.value("n", 0);
  i.frames = j.value("frames", 1);
  i.size = j.value("size", uint64_t(0));
  i.mtime = j.value("mtime", int64_t(0));
  i.stored = j.value("stored", false);
  return i;
}

}  // namespace

void ImportJournal::append(const std::string& lines) const {
  // O_APPEND: two processes importing at once each add whole lines.
  int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0600);
  if (fd < 0)
    throw outputError("Cannot write the study database journal " + path_ + " (" +
                      std::strerror(errno) + "): check that the folder is writable");
  size_t done = 0;
  while (done < lines.size()) {
    ssize_t n = ::write(fd, lines.data() + done, lines.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      int e = errno;
      ::close(fd);
      throw outputError("Cannot write the study database journal " + path_ + " (" +
                        std::strerror(e) + "): free space on its disk");
    }
    done += size_t(n);
  }
  ::close(fd);
}

void ImportJournal::appendAdd(const std::vector<InstanceRecord>& records) const {
  // Grouped by series, in the order they came.
  std::map<std::string, size_t> line;
  std::vector<json> lines;
  for (const auto& r : records) {
    auto [it, fresh] = line.emplace(r.series.uid, lines.size());
    if (fresh) {
      lines.push_back({{"op", "add"},
                       {"patient",
                        {{"id", r.patient.patientId},
                         {"name", r.patient.name},
                         {"birth", r.patient.birthDate},
                         {"sex", r.patient.sex}}},
                       {"study",
                        {{"uid", r.study.uid},
                         {"date", r.study.date},
                         {"time", r.study.time},
                         {"description", r.study.description},
                         {"accession", r.study.accession},
                         {"id", r.study.studyId}}},
                       {"series",
                        {{"uid", r.series.uid},
                         {"number", r.series.number},
                         {"description", r.series.description},
                         {"modality", r.series.modality},
                         {"body_part", r.series.bodyPart}}},
                       {"instances", json::array()}});
    }
    lines[it->second]["instances"].push_back(instanceJson(r.instance));
  }
  std::string text;
  for (const auto& j : lines) text += j.dump(-1, ' ', false, json::error_handler_t::replace) + "\n";
  if (!text.empty()) append(text);
}

void ImportJournal::appendDelete(JournalEntry::Op op, const std::string& uid) const {
  json j = {{"op", op == JournalEntry::Op::DeleteStudy ? "delete-study" : "delete-series"},
            {"uid", uid}};
  append(j.dump(-1, ' ', false, json::error_handler_t::replace) + "\n");
}

int ImportJournal::replay(const std::function<void(JournalEntry&)>& visit) const {
  std::ifstream in(path_);
  int damaged = 0;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    JournalEntry e;
    try {
      json j = json::parse(line);
      std::string op = j.at("op").get<std::string>();
      if (op == "add") {
        InstanceRecord base;
        const json& p = j.at("patient");
        base.patient = {p.value("id", ""), p.value("name", ""), p.value("birth", ""),
                        p.value("sex", "")};
        const json& s = j.at("study");
        base.study = {s.at("uid").get<std::string>(), s.value("date", ""),      s.value("time", ""),
                      s.value("description", ""),     s.value("accession", ""), s.value("id", "")};
        const json& se = j.at("series");
        base.series.uid = se.at("uid").get<std::string>();
        base.series.number = se.value("number", 0);
        base.series.description = se.value("description", "");
        base.series.modality = se.value("modality", "");
        base.series.bodyPart = se.value("body_part", "");
        for (const json& i : j.at("instances")) {
          InstanceRecord r = base;
          r.instance = instanceFrom(i);
          e.records.push_back(std::move(r));
        }
      } else if (op == "delete-study" || op == "delete-series") {
        e.op =
            op == "delete-study" ? JournalEntry::Op::DeleteStudy : JournalEntry::Op::DeleteSeries;
        e.uid = j.at("uid").get<std::string>();
      } else {
        ++damaged;
        continue;
      }
    } catch (const json::exception&) {
      ++damaged;
      continue;
    }
    visit(e);
  }
  return damaged;
}

}  // namespace voxray::studydb
