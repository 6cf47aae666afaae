"""Checks an anonymised export (`voxray-cli anonymise`) against its source with pydicom:
no value of a PS3.15 Basic Profile attribute survives (attribute by attribute, anywhere in
the dataset, sequences included), no private attribute is left, UIDs are new and mapped
one to one, the dates follow the option, and the pixels and geometry are the source's.

usage: check_anonymised.py SOURCE_FOLDER OUTPUT_FOLDER remove|keep|shift [DAYS]"""
import datetime
import hashlib
import sys
from pathlib import Path

try:
    import pydicom
except ImportError as e:
    sys.exit(f"{e}: run scripts/bootstrap (it makes the .venv with pydicom)")

source, output, mode = Path(sys.argv[1]), Path(sys.argv[2]), sys.argv[3]
days = int(sys.argv[4]) if mode == "shift" else 0

# PS3.15 Table E.1-1 (Basic Profile), by keyword: the attributes whose values must not
# survive. Written out here, apart from the exporter's table, so that the two can disagree.
PROFILE = """
InstanceCreatorUID InstanceCoercionDateTime SOPInstanceUID StudyDate SeriesDate AcquisitionDate
ContentDate OverlayDate CurveDate AcquisitionDateTime StudyTime SeriesTime AcquisitionTime
ContentTime OverlayTime CurveTime AccessionNumber FailedSOPInstanceUIDList InstitutionName
InstitutionAddress InstitutionCodeSequence ReferringPhysicianName ReferringPhysicianAddress
ReferringPhysicianTelephoneNumbers ReferringPhysicianIdentificationSequence
ConsultingPhysicianName ConsultingPhysicianIdentificationSequence TimezoneOffsetFromUTC
StationName StudyDescription SeriesDescription InstitutionalDepartmentName
InstitutionalDepartmentTypeCodeSequence PhysiciansOfRecord
PhysiciansOfRecordIdentificationSequence PerformingPhysicianName
PerformingPhysicianIdentificationSequence NameOfPhysiciansReadingStudy
PhysiciansReadingStudyIdentificationSequence OperatorsName OperatorIdentificationSequence
AdmittingDiagnosesDescription AdmittingDiagnosesCodeSequence ReferencedStudySequence
ReferencedPerformedProcedureStepSequence ReferencedPatientSequence ReferencedSOPInstanceUID
TransactionUID DerivationDescription IrradiationEventUID IdentifyingComments
InstanceCreationDate InstanceCreationTime
PatientName PatientID IssuerOfPatientID PatientBirthDate PatientBirthTime PatientSex
PatientInsurancePlanCodeSequence PatientPrimaryLanguageCodeSequence
PatientPrimaryLanguageModifierCodeSequence OtherPatientIDs OtherPatientNames
OtherPatientIDsSequence PatientBirthName PatientAge PatientSize PatientWeight PatientAddress
PatientMotherBirthName MilitaryRank BranchOfService MedicalRecordLocator MedicalAlerts
Allergies CountryOfResidence RegionOfResidence PatientTelephoneNumbers EthnicGroup Occupation
SmokingStatus AdditionalPatientHistory PregnancyStatus LastMenstrualDate
PatientReligiousPreference PatientSexNeutered ResponsiblePerson ResponsibleOrganization
PatientComments DeviceSerialNumber DeviceUID PlateID GeneratorID CassetteID GantryID
DateOfSecondaryCapture TimeOfSecondaryCapture ProtocolName DateOfLastCalibration
TimeOfLastCalibration AcquisitionDeviceProcessingDescription AcquisitionComments DetectorID
FrameAcquisitionDateTime FrameReferenceDateTime AcquisitionProtocolDescription
ContributionDescription StudyInstanceUID SeriesInstanceUID StudyID FrameOfReferenceUID
SynchronizationFrameOfReferenceUID ModifyingDeviceID ModifyingDeviceManufacturer
ModifiedImageDescription ImageComments ConcatenationUID DimensionOrganizationUID
PaletteColorLookupTableUID LargePaletteColorLookupTableUID ImagePresentationComments
StudyIDIssuer ScheduledStudyLocation ScheduledStudyLocationAETitle ReasonForStudy
RequestingPhysician RequestingService RequestedProcedureDescription RequestedContrastAgent
StudyComments ReferencedPatientAliasSequence AdmissionID IssuerOfAdmissionID
ScheduledPatientInstitutionResidence AdmittingDate AdmittingTime
DischargeDiagnosisDescription SpecialNeeds ServiceEpisodeID CurrentPatientLocation
PatientInstitutionResidence PatientState VisitComments ScheduledStationAETitle
ScheduledProcedureStepStartDate ScheduledProcedureStepStartTime ScheduledProcedureStepEndDate
ScheduledProcedureStepEndTime ScheduledPerformingPhysicianName
ScheduledProcedureStepDescription ScheduledPerformingPhysicianIdentificationSequence
ScheduledStationName ScheduledProcedureStepLocation PreMedication PerformedStationAETitle
PerformedStationName PerformedLocation PerformedProcedureStepStartDate
PerformedProcedureStepStartTime PerformedProcedureStepEndDate PerformedProcedureStepEndTime
PerformedProcedureStepID PerformedProcedureStepDescription RequestAttributesSequence
CommentsOnThePerformedProcedureStep AcquisitionContextSequence RequestedProcedureID
PatientTransportArrangements RequestedProcedureLocation NamesOfIntendedRecipientsOfResults
IntendedRecipientsOfResultsIdentificationSequence PersonIdentificationCodeSequence
PersonAddress PersonTelephoneNumbers RequestedProcedureComments
ReasonForTheImagingServiceRequest OrderEnteredBy OrderEntererLocation
OrderCallbackPhoneNumber PlacerOrderNumberImagingServiceRequest
FillerOrderNumberImagingServiceRequest ImagingServiceRequestComments
ConfidentialityConstraintOnPatientDataDescription VerifyingOrganization
VerifyingObserverSequence VerifyingObserverName AuthorObserverSequence ParticipantSequence
CustodialOrganizationSequence VerificationDateTime ObservationDateTime DateTime Date Time UID
ObservationUID ContentSequence ContentCreatorName ContentCreatorIdentificationCodeSequence
FiducialUID StorageMediaFileSetUID DigitalSignatureUID ReferencedDigitalSignatureSequence
ReferencedSOPInstanceMACSequence MAC ModifiedAttributesSequence OriginalAttributesSequence
ReferencedFrameOfReferenceUID RelatedFrameOfReferenceUID TextComments ResultsIDIssuer
PhysicianApprovingInterpretation DistributionName DistributionAddress InterpretationIDIssuer
ResultsComments DigitalSignaturesSequence DataSetTrailingPadding
""".split()
TEMPORAL = {"DA", "DT", "TM"}
OWN_WORDS = {"ANONYMOUS", "REMOVED", "MODIFIED", "UNMODIFIED", "YES"}
GEOMETRY = ["ImagePositionPatient", "ImageOrientationPatient", "PixelSpacing", "SliceThickness",
            "RescaleSlope", "RescaleIntercept", "Rows", "Columns", "BitsStored",
            "PixelRepresentation", "GantryDetectorTilt", "Modality", "SOPClassUID"]
failures = []


def fail(what):
    if len(failures) < 40:
        failures.append(what)


def elements(ds):
    for e in ds:
        yield e
        if e.VR == "SQ":
            for item in e.value:
                yield from elements(item)


def values(ds, keyword):
    tag = pydicom.datadict.tag_for_keyword(keyword)
    out = []
    for e in elements(ds):
        if e.tag == tag and e.value not in (None, "", b""):
            if e.VR == "SQ":
                out.append(("SQ", len(e.value)))
            else:
                out.extend(str(v) for v in (e.value if e.VM > 1 else [e.value]))
    return out


def key(ds):
    return (tuple(map(float, ds.ImagePositionPatient)),
            hashlib.sha1(ds.PixelData).hexdigest())


src = {}
for p in sorted(q for q in source.rglob("*") if q.is_file()):
    try:
        d = pydicom.dcmread(p)
    except Exception:
        continue
    if "PixelData" in d:
        src[key(d)] = (p, d)
out = {}
for p in sorted(output.rglob("*.dcm")):
    d = pydicom.dcmread(p)
    out[key(d)] = (p, d)
if len(out) != len(src) or set(out) != set(src):
    sys.exit(f"{len(out)} anonymised images for {len(src)} source images, or their pixels differ")

source_uids = {v for _, d in src.values() for e in elements(d) if e.VR == "UI"
               for v in (e.value if e.VM > 1 else [e.value])}
uid_map = {}
checked = set()
for k, (sp, s) in src.items():
    op, o = out[k]
    raw = op.read_bytes()
    for kw in PROFILE:
        before, after = values(s, kw), values(o, kw)
        if not before:
            continue
        checked.add(kw)
        vr = pydicom.datadict.dictionary_VR(pydicom.datadict.tag_for_keyword(kw))
        if vr in TEMPORAL and mode == "keep":
            if before != after:
                fail(f"{op.name}: {kw} {after} should be kept as {before}")
            continue
        if vr in TEMPORAL and mode == "shift" and vr != "TM":
            want = [(datetime.date(int(v[:4]), int(v[4:6]), int(v[6:8])) +
                     datetime.timedelta(days=days)).strftime("%Y%m%d") + v[8:] for v in before]
            if after != want:
                fail(f"{op.name}: {kw} {after} should be {want} ({days} days)")
            continue
        if vr in TEMPORAL and mode == "shift":
            continue  # times stay with the Modified Dates option
        kept = [v for v in after if v in before]
        if kept:
            fail(f"{op.name}: {kw} keeps its value")
        if vr == "UI":
            for v in after:
                if v in source_uids:
                    fail(f"{op.name}: {kw} is a source UID")
            for a, b in zip(values(s, kw), values(o, kw)):
                if uid_map.setdefault(a, b) != b:
                    fail(f"{kw}: {a} maps to two new UIDs")
    for e in elements(o):
        if e.tag.is_private:
            fail(f"{op.name}: private attribute {e.tag} left")
    for kw in ("PatientName", "PatientID"):
        v = str(s.get(kw, ""))
        # A source already de-identified may be named with a word the export writes itself
        # (ct-ge-tilt's "REMOVED" is also LongitudinalTemporalInformationModified's value).
        if len(v) >= 3 and v.encode() in raw and v not in OWN_WORDS:
            fail(f"{op.name}: the source's {kw} is still in the file's bytes")
    if o.get("PatientIdentityRemoved") != "YES":
        fail(f"{op.name}: PatientIdentityRemoved is not YES")
    codes = [c.CodeValue for c in o.get("DeidentificationMethodCodeSequence", [])]
    want = ["113100"] + {"keep": ["113106"], "shift": ["113107"], "remove": []}[mode]
    if codes != want:
        fail(f"{op.name}: de-identification codes {codes} != {want}")
    for kw in GEOMETRY:
        if s.get(kw) is not None and str(s.get(kw).value if hasattr(s.get(kw), "value") else s.get(kw)) != \
                str(o.get(kw).value if hasattr(o.get(kw), "value") else o.get(kw)):
            fail(f"{op.name}: {kw} changed")
    if o.file_meta.MediaStorageSOPInstanceUID != o.SOPInstanceUID:
        fail(f"{op.name}: meta header's SOP Instance UID is not the dataset's")
    if o.file_meta.TransferSyntaxUID != s.file_meta.TransferSyntaxUID:
        fail(f"{op.name}: transfer syntax changed")

news = [d for _, d in out.values()]
for kw in ("StudyInstanceUID", "SeriesInstanceUID", "FrameOfReferenceUID"):
    if len({d.get(kw) for d in news}) != len({d.get(kw) for _, d in src.values()}):
        fail(f"{kw}: the export does not keep one new UID per old one")
if len({d.SOPInstanceUID for d in news}) != len(news):
    fail("SOP Instance UIDs are not unique")
for must in ("SOPInstanceUID", "StudyInstanceUID", "PatientName", "PatientID"):
    if must not in checked:
        fail(f"the source had no {must}: this check proved nothing about it")
if failures:
    sys.exit("\n".join(failures))
print(f"{len(out)} images: {len(checked)} profile attributes of the source checked "
      f"({', '.join(sorted(checked))}), none kept; pixels and geometry unchanged")
