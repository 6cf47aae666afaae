// The DIMSE transport: C-ECHO, C-FIND, C-GET, C-MOVE (into Voxray's own receiver) and
// C-STORE through DCMTK's DcmSCU.
#include <algorithm>
#include <filesystem>
#include <functional>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmnet/scu.h>

#include "cancellable_transport.h"
#include "dimse_support.h"
#include "match_values.h"
#include "move_receiver.h"
#include "pacs_messages.h"
#include "sendable.h"
#include "transports.h"
#include "voxray/io/error.h"
#include "voxray/io/pacs.h"

namespace voxray::pacs {
namespace {

// All sub-operations of a retrieval, done and to do: the number of images.
int subops(const RetrieveResponse& r) {
  return int(r.m_numberOfRemainingSubops) + int(r.m_numberOfCompletedSubops) +
         int(r.m_numberOfFailedSubops) + int(r.m_numberOfWarningSubops);
}

// A DcmSCU that stores C-GET's incoming instances into a folder, reports progress, stops on
// cancel and hands C-FIND matches to a callback as they come (which may ask the node to stop
// with C-CANCEL by returning false).
class Scu : public DcmSCU {
 public:
  std::function<bool(DcmDataset&)> onFindMatch;
  std::string folder;
  std::vector<std::string> files;
  RetrieveOptions retrieve;
  RetrieveProgress progress;
  bool findCancelSent = false;
  bool cancelled = false;
  std::string storeError;
  // Every wait for the node stops on cancel and once it has sent nothing for its timeout.
  std::shared_ptr<IdleDeadline> idle;
  std::unique_ptr<CancellableTransport> transport;

  // DCMTK's only hook for the connection class (it asks for no TLS of its own).
  OFCondition useTransport(DcmTransportLayer* layer) { return useSecureConnection(layer); }

  // The association goes before the transport its connection came from.
  ~Scu() override {
    if (isConnected()) abortAssociation();
  }

  OFCondition handleSTORERequest(const T_ASC_PresentationContextID, DcmDataset* incoming,
                                 OFBool& continueSession, Uint16& status) override {
    DcmFileFormat file(incoming, OFFalse);  // takes ownership
    status = STATUS_Success;
    continueSession = OFTrue;
    if (retrieve.cancel && retrieve.cancel->load()) {
      cancelled = true;
      continueSession = OFFalse;
      status = STATUS_STORE_Refused_OutOfResources;
      return EC_Normal;
    }
    OFString uid;
    incoming->findAndGetOFString(DCM_SOPInstanceUID, uid);
    std::string name = uid.c_str();
    name.erase(std::remove_if(name.begin(), name.end(),
                              [](char c) { return !(std::isdigit(uchar(c)) || c == '.'); }),
               name.end());
    if (name.empty()) name = "instance-" + std::to_string(files.size());
    std::string path = folder + "/" + name + ".dcm";
    OFCondition cond = file.saveFile(path.c_str(), incoming->getOriginalXfer());
    if (cond.bad()) {
      storeError = "cannot write " + path + " (" + cond.text() + "): check free space";
      status = STATUS_STORE_Refused_OutOfResources;
      continueSession = OFFalse;
      return EC_Normal;
    }
    files.push_back(path);
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(path, ec);
    if (!ec) progress.megabytes += double(bytes) / 1e6;
    progress.received = int(files.size());
    progress.total = std::max(progress.total, progress.received);
    if (retrieve.progress) retrieve.progress(progress);
    return EC_Normal;
  }

  OFCondition handleCGETResponse(const T_ASC_PresentationContextID id, RetrieveResponse* response,
                                 OFBool& continueSession) override {
    progress.total = std::max(progress.total, subops(*response));
    return DcmSCU::handleCGETResponse(id, response, continueSession);
  }

  std::function<void(int)> onMoveTotal;
  OFCondition handleMOVEResponse(const T_ASC_PresentationContextID id, RetrieveResponse* response,
                                 OFBool& waitForNext) override {
    if (onMoveTotal) onMoveTotal(subops(*response));
    return DcmSCU::handleMOVEResponse(id, response, waitForNext);
  }

  OFCondition handleFINDResponse(const T_ASC_PresentationContextID id, QRResponse* response,
                                 OFBool& waitForNext) override {
    if (response->m_dataset && onFindMatch && !findCancelSent &&
        !onFindMatch(*response->m_dataset)) {
      findCancelSent = true;
      sendCANCELRequest(id);
    }
    return DcmSCU::handleFINDResponse(id, response, waitForNext);
  }
};

// QueryRetrieveLevel, in the order of QueryLevel.
const char* levelName(QueryLevel level) {
  static const char* const names[] = {"PATIENT", "STUDY", "SERIES"};
  return names[int(level)];
}

std::string text(DcmDataset& d, const DcmTagKey& tag) {
  OFString value;
  d.findAndGetOFStringArray(tag, value);
  return value.c_str();
}

int number(DcmDataset& d, const DcmTagKey& tag) { return countValue(text(d, tag)); }

class DimseClient : public PacsClient {
  PacsNode node_;

 public:
  explicit DimseClient(PacsNode node) : node_(std::move(node)) {}

  void echo() override {
    auto scu = connect("C-ECHO", [](Scu& s) {
      s.addPresentationContext(UID_VerificationSOPClass, acceptedTransferSyntaxes());
    });
    check("C-ECHO", scu->sendECHORequest(0), *scu);
    scu->releaseAssociation();
  }

  FindResult findPages(const PacsQuery& q, const FindOptions& options) override {
    const char* model = q.level == QueryLevel::Patient
                            ? UID_FINDPatientRootQueryRetrieveInformationModel
                            : UID_FINDStudyRootQueryRetrieveInformationModel;
    auto scu = connect(
        "C-FIND", [&](Scu& s) { s.addPresentationContext(model, acceptedTransferSyntaxes()); },
        options.cancel);
    DcmDataset keys;
    keys.putAndInsertString(DCM_QueryRetrieveLevel, levelName(q.level));
    keys.putAndInsertString(DCM_PatientName, q.patientName.c_str());
    keys.putAndInsertString(DCM_PatientID, q.patientId.c_str());
    if (q.level != QueryLevel::Patient) {
      std::string dates = q.dateFrom.empty() && q.dateTo.empty() ? "" : q.dateFrom + "-" + q.dateTo;
      keys.putAndInsertString(DCM_StudyDate, dates.c_str());
      keys.putAndInsertString(DCM_StudyInstanceUID, q.studyInstanceUid.c_str());
      keys.putAndInsertString(DCM_StudyDescription, "");
      keys.putAndInsertString(DCM_AccessionNumber, q.accessionNumber.c_str());
    }
    if (q.level == QueryLevel::Study) {
      keys.putAndInsertString(DCM_ModalitiesInStudy, q.modality.c_str());
      keys.putAndInsertString(DCM_NumberOfStudyRelatedSeries, "");
      keys.putAndInsertString(DCM_NumberOfStudyRelatedInstances, "");
    } else if (q.level == QueryLevel::Series) {
      keys.putAndInsertString(DCM_Modality, q.modality.c_str());
      keys.putAndInsertString(DCM_SeriesInstanceUID, "");
      keys.putAndInsertString(DCM_SeriesDescription, "");
      keys.putAndInsertString(DCM_SeriesNumber, "");
      keys.putAndInsertString(DCM_NumberOfSeriesRelatedInstances, "");
    }
    // C-FIND has no paging: matches arrive one by one and are handed over in pages. One
    // match past the limit (or the cap) tells that the node holds more; then C-CANCEL stops
    // it.
    FindResult result;
    std::vector<PacsMatch> page;
    auto flush = [&] {
      if (options.page && !page.empty()) options.page(page);
      page.clear();
    };
    const size_t limit = q.limit ? std::min(q.limit, options.maxMatches) : options.maxMatches;
    scu->onFindMatch = [&](DcmDataset& d) {
      if (options.cancel && options.cancel->load()) return false;
      if (result.matches.size() >= limit) {
        result.more = true;
        return false;
      }
      result.matches.push_back(toMatch(d, q.level));
      page.push_back(result.matches.back());
      if (page.size() >= std::max<size_t>(options.pageSize, 1)) flush();
      return true;
    };
    OFCondition cond =
        scu->sendFINDRequest(scu->findPresentationContextID(model, ""), &keys, nullptr);
    if (options.cancel && options.cancel->load()) {  // C-CANCEL sent, or a wait stopped
      scu->abortAssociation();
      throw cancelledError("Search cancelled");
    }
    check("C-FIND", cond, *scu);
    scu->releaseAssociation();
    flush();
    return result;
  }

  std::vector<std::string> retrieveSeries(const std::string& studyUid, const std::string& seriesUid,
                                          const std::string& folder,
                                          const RetrieveOptions& options) override {
    DcmDataset keys;
    keys.putAndInsertString(DCM_QueryRetrieveLevel, "SERIES");
    keys.putAndInsertString(DCM_StudyInstanceUID, studyUid.c_str());
    keys.putAndInsertString(DCM_SeriesInstanceUID, seriesUid.c_str());
    if (node_.receivePort > 0) return move(keys, folder, options);
    auto scu = connect(
        "C-GET",
        [](Scu& s) {
          s.addPresentationContext(UID_GETStudyRootQueryRetrieveInformationModel,
                                   acceptedTransferSyntaxes());
          for (int i = 0; i < storageSopClassCount(); ++i)
            s.addPresentationContext(storageSopClass(i), acceptedTransferSyntaxes(),
                                     ASC_SC_ROLE_SCP);
        },
        options.cancel);
    scu->folder = folder;
    scu->retrieve = options;
    OFList<RetrieveResponse*> responses;
    OFCondition cond = scu->sendCGETRequest(
        scu->findPresentationContextID(UID_GETStudyRootQueryRetrieveInformationModel, ""), &keys,
        &responses);
    int failed = 0;
    for (RetrieveResponse* r : responses) {
      failed = std::max(failed, int(r->m_numberOfFailedSubops));
      delete r;
    }
    if (scu->cancelled || (options.cancel && options.cancel->load())) {
      scu->abortAssociation();
      throw cancelledError("Retrieval cancelled");
    }
    if (!scu->storeError.empty()) throw outputError(scu->storeError);
    check("C-GET", cond, *scu);
    scu->releaseAssociation();
    finish("C-GET", scu->files, failed, scu->progress.total, keys);
    return scu->files;
  }

  void store(const std::vector<std::string>& files, const std::atomic<bool>* cancel) override {
    std::vector<SendableFile> loaded = loadSendableFiles(files);
    auto scu = connect(
        "C-STORE",
        [&](Scu& s) {
          for (auto& f : loaded) {
            OFString sopClass;
            f.dicom->getDataset()->findAndGetOFString(DCM_SOPClassUID, sopClass);
            OFList<OFString> xfer;
            xfer.push_back(DcmXfer(f.dicom->getDataset()->getOriginalXfer()).getXferID());
            if (s.findPresentationContextID(sopClass, xfer.front()) == 0)
              s.addPresentationContext(sopClass, xfer);
          }
        },
        cancel);
    for (size_t i = 0; i < files.size(); ++i) {
      if (cancel && cancel->load()) {
        scu->abortAssociation();
        throw cancelledError("Sending cancelled after " + std::to_string(i) + " of " +
                             std::to_string(files.size()) + " files");
      }
      Uint16 status = 0;
      OFCondition cond = scu->sendSTORERequest(0, "", loaded[i].dicom->getDataset(), status);
      if (cancel && cancel->load()) {  // a wait for the node stopped
        scu->abortAssociation();
        throw cancelledError("Sending cancelled during file " + std::to_string(i + 1) + " of " +
                             std::to_string(files.size()) +
                             "; the node may keep the files before it");
      }
      check("C-STORE of " + files[i], cond, *scu);
      if (status != STATUS_Success)
        throw inputError("PACS " + node_.label() + " refused " + files[i] + " (status 0x" +
                         hexStatus(status) + "); nothing after it was sent");
    }
    scu->releaseAssociation();
  }

 private:
  // An association for WHAT; with CANCEL, every wait for the node stops when it becomes true
  // (Cancelled, saying the node had not answered, when that happens before it accepted).
  template <class Setup>
  std::unique_ptr<Scu> connect(const std::string& what, Setup setup,
                               const std::atomic<bool>* cancel = nullptr,
                               std::shared_ptr<IdleDeadline> idle = nullptr) {
    auto scu = std::make_unique<Scu>();
    scu->idle = idle ? std::move(idle) : std::make_shared<IdleDeadline>(node_.timeoutSec);
    scu->setAETitle(node_.callingAe.c_str());
    scu->setPeerAETitle(node_.calledAe.c_str());
    scu->setPeerHostName(node_.host.c_str());
    scu->setPeerPort(Uint16(node_.port));
    scu->setConnectionTimeout(node_.timeoutSec);
    scu->setACSETimeout(Uint32(node_.timeoutSec));
    scu->setDIMSETimeout(Uint32(node_.timeoutSec));
    scu->setDIMSEBlockingMode(DIMSE_NONBLOCKING);
    scu->setMaxReceivePDULength(ASC_MAXIMUMPDUSIZE);
    setup(*scu);
    check(what + ": network setup", scu->initNetwork(), *scu);
    scu->transport = std::make_unique<CancellableTransport>(cancel, scu->idle.get());
    check(what + ": network setup", scu->useTransport(scu->transport.get()), *scu);
    if (cancel) {
      ConnectCheck c = checkConnect(node_.host, node_.port, node_.timeoutSec, cancel);
      if (c == ConnectCheck::Cancelled)
        throw cancelledError(what + " cancelled: PACS " + node_.label() +
                             " had not accepted the TCP connection; nothing was exchanged");
      if (c == ConnectCheck::TimedOut)
        throw inputError("PACS " + node_.label() + ": " + what +
                         ": the host did not accept the TCP connection within " +
                         std::to_string(node_.timeoutSec) +
                         " s: check that the node is running and its host and port are right");
    }
    scu->idle->touch();  // the association's first wait starts now
    OFCondition cond = scu->negotiateAssociation();
    if (cancel && cancel->load())
      throw cancelledError(cond.good() ? what + " cancelled; nothing was exchanged"
                                       : what + " cancelled: PACS " + node_.label() +
                                             " had not answered the association request (it "
                                             "took the connection and said nothing); nothing "
                                             "was exchanged");
    check(what + ": cannot associate", cond, *scu);
    return scu;
  }

  // A failed exchange; once the node has sent nothing for its timeout, that is the reason.
  void check(const std::string& what, const OFCondition& cond, const Scu& scu) const {
    if (cond.bad() && scu.idle->passed()) throw inputError(stalledMessage(node_, what));
    if (cond.bad()) throw inputError(dimseFailure(node_, what, cond));
  }

  // After a retrieval: no image and none announced (TOTAL: the sub-operations the node
  // reported) is a series the node does not hold; fewer than all is an incomplete one.
  void finish(const std::string& what, const std::vector<std::string>& files, int failed, int total,
              DcmDataset& keys) {
    if (files.empty() && failed == 0 && total == 0) {
      OFString study, series;
      keys.findAndGetOFString(DCM_StudyInstanceUID, study);
      keys.findAndGetOFString(DCM_SeriesInstanceUID, series);
      throw inputError(noSuchSeries(study.c_str(), series.c_str()));
    }
    if (failed > 0 || files.empty())
      throw inputError("PACS " + node_.label() + ": " + what + " delivered " +
                       std::to_string(files.size()) + " images" +
                       (failed ? ", " + std::to_string(failed) + " failed" : std::string()) +
                       ": the series is incomplete and was not kept; try again");
  }

  // Which of the two UIDs the node does not know: a study-level C-FIND tells.
  std::string noSuchSeries(const std::string& study, const std::string& series) {
    PacsQuery q;
    q.studyInstanceUid = study;
    q.limit = 1;
    bool studyKnown = true;
    try {
      studyKnown = !findPages(q, {}).matches.empty();
    } catch (const Error&) {
      // The search failed: name both UIDs, as if the study were there.
    }
    return unknownSeriesMessage(node_, study, series, studyKnown);
  }

  std::vector<std::string> move(DcmDataset& keys, const std::string& folder,
                                const RetrieveOptions& options) {
    // The images arrive at the receiver: they count as the node's answer for both.
    auto idle = std::make_shared<IdleDeadline>(node_.timeoutSec);
    MoveReceiver receiver(node_, folder, options, idle.get());
    auto scu = connect(
        "C-MOVE",
        [](Scu& s) {
          s.addPresentationContext(UID_MOVEStudyRootQueryRetrieveInformationModel,
                                   acceptedTransferSyntaxes());
        },
        options.cancel, idle);
    int total = 0;
    scu->onMoveTotal = [&](int n) {
      total = std::max(total, n);
      receiver.setTotal(n);
    };
    OFList<RetrieveResponse*> responses;
    OFCondition cond = scu->sendMOVERequest(
        scu->findPresentationContextID(UID_MOVEStudyRootQueryRetrieveInformationModel, ""),
        node_.callingAe.c_str(), &keys, &responses);
    int failed = 0;
    for (RetrieveResponse* r : responses) {
      failed = std::max(failed, int(r->m_numberOfFailedSubops));
      delete r;
    }
    std::vector<std::string> files = receiver.finish();
    if (options.cancel && options.cancel->load()) {
      scu->abortAssociation();
      throw cancelledError("Retrieval cancelled");
    }
    check("C-MOVE", cond, *scu);
    scu->releaseAssociation();
    finish("C-MOVE to AE " + node_.callingAe + " port " + std::to_string(node_.receivePort), files,
           failed, total, keys);
    return files;
  }

  static std::string hexStatus(Uint16 status) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "%04X", unsigned(status));
    return buf;
  }

  static PacsMatch toMatch(DcmDataset& d, QueryLevel level) {
    PacsMatch m;
    m.patientName = text(d, DCM_PatientName);
    m.patientId = text(d, DCM_PatientID);
    m.studyInstanceUid = text(d, DCM_StudyInstanceUID);
    m.studyDate = text(d, DCM_StudyDate);
    m.studyDescription = text(d, DCM_StudyDescription);
    m.accessionNumber = text(d, DCM_AccessionNumber);
    m.modalities = text(d, level == QueryLevel::Series ? DCM_Modality : DCM_ModalitiesInStudy);
    m.numberOfSeries = number(d, DCM_NumberOfStudyRelatedSeries);
    m.numberOfInstances =
        number(d, level == QueryLevel::Series ? DCM_NumberOfSeriesRelatedInstances
                                              : DCM_NumberOfStudyRelatedInstances);
    m.seriesInstanceUid = text(d, DCM_SeriesInstanceUID);
    m.seriesDescription = text(d, DCM_SeriesDescription);
    m.seriesNumber = number(d, DCM_SeriesNumber);
    return m;
  }
};

}  // namespace

std::unique_ptr<PacsClient> makeDimseClient(const PacsNode& node) {
  return std::make_unique<DimseClient>(node);
}

}  // namespace voxray::pacs
