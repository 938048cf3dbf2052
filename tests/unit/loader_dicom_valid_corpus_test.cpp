// The pre-check (dicom_guard) held to valid files and hostile ones: it must never refuse a file
// GDCM reads correctly (a refused slice is a slice lost from its series), and must refuse what
// would crash, abort or exhaust GDCM.
#include <gdcmImageReader.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "dicom_byte_files.h"
#include "io/dicom_guard.h"
#include "io/format_loaders.h"
#include "medical_test_files.h"

namespace ewa {
namespace {

using namespace testing;

bool gdcmReadsImage(const std::string& path) {
  gdcm::ImageReader reader;
  reader.SetFileName(path.c_str());
  return reader.Read();
}

// Expects GDCM to read each file as an image and the pre-check to pass it.
void expectPassed(const std::vector<std::string>& files) {
  for (const std::string& file : files) {
    if (!gdcmReadsImage(file)) {
      ADD_FAILURE() << "GDCM does not read " << file << ": not a valid corpus file";
      continue;
    }
    try {
      EXPECT_EQ(checkDicomStructure(file), DicomStructure::Plausible) << file;
    } catch (const LoadError& e) {
      ADD_FAILURE() << "refused a file GDCM reads: " << e.what();
    }
  }
}

// Every kind of DICOM file the tests make: GDCM's writers in each syntax, enhanced files, bare
// data sets, hand-made ones (deflated, padded, nested, RT Dose).
std::vector<std::string> generatedCorpus(const TempDir& dir) {
  gdcm::Trace::WarningOff();
  std::vector<std::string> files;
  // 64 x 64: GDCM's JPEG 2000 encoder overruns its buffer on tiny images.
  DicomSliceSpec spec;
  spec.rows = spec.columns = 64;
  spec.slope = 2.0;
  spec.intercept = -5.0;
  const std::string series = dicomSeries(dir, "gdcm", 1, spec);
  files.push_back(series + "/im0.dcm");
  DicomSliceSpec rgb;
  rgb.rows = rgb.columns = 64;
  rgb.rgb = true;
  files.push_back(dicomSeries(dir, "rgb", 1, rgb) + "/im0.dcm");
  rgb.planar = true;
  files.push_back(dicomSeries(dir, "planar", 1, rgb) + "/im0.dcm");
  int n = 0;
  for (const auto syntax :
       {gdcm::TransferSyntax::ImplicitVRLittleEndian, gdcm::TransferSyntax::ExplicitVRBigEndian,
        gdcm::TransferSyntax::RLELossless, gdcm::TransferSyntax::JPEGLosslessProcess14_1,
        gdcm::TransferSyntax::JPEGBaselineProcess1, gdcm::TransferSyntax::JPEGLSLossless,
        gdcm::TransferSyntax::JPEG2000Lossless}) {
    for (const std::string& from : {files[0], files[1]}) {
      // Baseline JPEG is 8-bit: the RGB image only.
      if (syntax == gdcm::TransferSyntax::JPEGBaselineProcess1 && from == files[0]) continue;
      const std::string to = dir.path("syntax" + std::to_string(n++) + ".dcm");
      std::filesystem::copy_file(from, to);
      EXPECT_TRUE(recompressDicom(to, syntax)) << int(syntax);
      files.push_back(to);
    }
  }
  // GDCM's deflating writer.
  const std::string gdcmDeflated = dir.path("gdcm_deflated.dcm");
  {
    gdcm::Reader reader;
    reader.SetFileName(files[0].c_str());
    EXPECT_TRUE(reader.Read());
    reader.GetFile().GetHeader().SetDataSetTransferSyntax(
        gdcm::TransferSyntax::DeflatedExplicitVRLittleEndian);
    gdcm::Writer writer;
    writer.SetFile(reader.GetFile());
    writer.SetFileName(gdcmDeflated.c_str());
    EXPECT_TRUE(writer.Write());
  }
  files.push_back(gdcmDeflated);
  EnhancedDicomSpec enhanced;
  files.push_back(dir.path("enhanced.dcm"));
  EXPECT_TRUE(writeEnhancedDicom(files.back(), enhanced));
  // A private value that opens like an item (then claims far more than it holds): GDCM keeps
  // an implicit file's defined-length values as bytes, and reads the file.
  files.push_back(dir.path("private_item_like.dcm"));
  std::filesystem::copy_file(files[3], files.back());
  EXPECT_TRUE(editDicom(files.back(), [](gdcm::DataSet& ds) {
    gdcm::DataElement creator(gdcm::Tag(0x0009, 0x0010));
    creator.SetByteValue("ACME", 4);
    ds.Insert(creator);
    const std::string value = uintBytes(0xfffe, 2) + uintBytes(0xe000, 2) +
                              uintBytes(0xffffff00u, 4) + std::string(8, 'x');
    gdcm::DataElement data(gdcm::Tag(0x0009, 0x1001));
    data.SetByteValue(value.data(), uint32_t(value.size()));
    ds.Insert(data);
  }));
  // Bare data sets (ACR-NEMA style), explicit and implicit.
  files.push_back(dir.write("IM0001", bareDataSet(files[0])));
  files.push_back(dir.write("IM0002", bareDataSet(files[3])));
  // Hand-made: plain, deflated, padded in each, nested to the limit, an RT Dose grid.
  const std::string image = imageDataSet({});
  files.push_back(dir.write("bytes.dcm", part10(image, kExplicitLittle)));
  files.push_back(dir.write("bytes_deflated.dcm", part10(rawDeflate(image), kDeflated)));
  files.push_back(
      dir.write("bytes_padded.dcm", part10(image + std::string(4099, '\0'), kExplicitLittle)));
  files.push_back(dir.write("bytes_deflated_padded.dcm",
                            part10(rawDeflate(image + std::string(3, '\0')), kDeflated)));
  files.push_back(dir.write("gdcm_padded.dcm", fileBytes(files[0]) + std::string(2400000, '\0')));
  files.push_back(
      dir.write("gdcm_implicit_padded.dcm", fileBytes(files[3]) + std::string(3, '\0')));
  files.push_back(dir.write("gdcm_rle_padded.dcm", fileBytes(files[7]) + std::string(4099, '\0')));
  ByteImageSpec nested;
  nested.beforePixels = nestedSequences(128);
  files.push_back(dir.write("nested.dcm", part10(imageDataSet(nested), kExplicitLittle)));
  ByteImageSpec dose;
  dose.sopClass = "1.2.840.10008.5.1.4.1.1.481.2";
  dose.modality = "RTDOSE";
  dose.frames = 3;
  dose.beforePixels = explicitElement(0x3004, 0x000c, "DS", evenText("0\\5\\10"));
  files.push_back(dir.write("dose.dcm", part10(imageDataSet(dose), kExplicitLittle)));
  return files;
}

TEST(DicomValidCorpus, ThePreCheckPassesEveryGeneratedFileGdcmReads) {
  TempDir dir;
  const std::vector<std::string> files = generatedCorpus(dir);
  EXPECT_GE(files.size(), 30u);
  expectPassed(files);
}

TEST(DicomValidCorpus, ThePreCheckPassesEverySharedDicomFile) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(EWA_SHARED_DATA))
    GTEST_SKIP() << "shared data folder " << EWA_SHARED_DATA << " is absent";
  std::vector<std::string> files;
  TempDir dir;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(EWA_SHARED_DATA, ec), end; !ec && it != end;
       it.increment(ec)) {
    const std::string file = it->path().string();
    if (it->is_regular_file() && looksLikeDicom(file)) files.push_back(file);
    // Zipped series, unpacked by unzip (not our reader) where it is installed.
    if (it->path().extension() == ".zip" && file.find("dicom") != std::string::npos) {
      const std::string to = dir.path("zip" + std::to_string(files.size()));
      const std::string command = "unzip -q -o '" + file + "' -d '" + to + "' >/dev/null 2>&1";
      if (std::system(command.c_str()) != 0) continue;
      for (const auto& inner : fs::recursive_directory_iterator(to))
        if (inner.is_regular_file() && looksLikeDicom(inner.path().string()))
          files.push_back(inner.path().string());
    }
  }
  EXPECT_GE(files.size(), 299u);  // dicom-pet's slices at least
  expectPassed(files);
}

TEST(DicomValidCorpus, ThePreCheckRefusesEveryHostileFile) {
  TempDir dir;
  const std::string image = imageDataSet({});
  ByteImageSpec deep, openItem, liar;
  deep.beforePixels = nestedSequences(5000);
  openItem.beforePixels = undefinedLength(0x0040, 0xa730, "SQ") + itemStart();
  liar.beforePixels = uintBytes(0x0040, 2) + uintBytes(0xa170, 2) + "OB" + std::string(2, '\0') +
                      uintBytes(0xfffffff0u, 4);
  ByteImageSpec dose;  // one frame, one offset: GDCM's reader asserts
  dose.sopClass = "1.2.840.10008.5.1.4.1.1.481.2";
  dose.beforePixels = explicitElement(0x3004, 0x000c, "DS", evenText("0"));
  const std::vector<std::string> hostile = {
      part10(imageDataSet(dose), kExplicitLittle, dose.sopClass),
      part10(imageDataSet(deep), kExplicitLittle),
      part10(rawDeflate(imageDataSet(deep)), kDeflated),
      part10(rawDeflate(imageDataSet(openItem)), kDeflated),
      part10(rawDeflate(imageDataSet(liar)), kDeflated),
      part10(rawDeflate(undefinedLength(0x0040, 0xa170, "OB")), kDeflated),
      part10(rawDeflate(image).substr(0, 20), kDeflated),
      part10(image + std::string(8, '\0') + "\x08", kExplicitLittle),
  };
  for (size_t n = 0; n < hostile.size(); ++n) {
    const std::string file = dir.write("hostile" + std::to_string(n) + ".dcm", hostile[n]);
    EXPECT_THROW(checkDicomStructure(file), LoadError) << file;
  }
}

}  // namespace
}  // namespace ewa
