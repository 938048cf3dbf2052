// Writes the window test's DICOM folder: two series of one patient, a ball (30 slices) and a
// box (20 slices), through the unit tests' GDCM helpers.   Usage: ewa_window_fixture FOLDER
#include <cstdio>
#include <filesystem>
#include <string>

#include "medical_test_files.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: ewa_window_fixture FOLDER\n");
    return 2;
  }
  const std::string folder = argv[1];
  std::filesystem::create_directories(folder);
  ewa::testing::DicomSliceSpec spec;
  spec.rows = spec.columns = 40;
  spec.rowSpacing = spec.columnSpacing = 1.0;
  auto write = [&](const std::string& name, int slices, auto inside) {
    for (int k = 0; k < slices; ++k) {
      spec.position = {0.0, 0.0, double(k)};
      spec.values.assign(40 * 40, 0);
      for (int j = 0; j < 40; ++j)
        for (int i = 0; i < 40; ++i)
          if (inside(i, j, k)) spec.values[size_t(40 * j + i)] = 1000;
      if (!ewa::testing::writeDicomSlice(folder + "/" + name + std::to_string(k) + ".dcm", spec))
        return false;
    }
    return true;
  };
  const bool ok =
      write("ball", 30,
            [](int i, int j, int k) {
              return (i - 20) * (i - 20) + (j - 20) * (j - 20) + (k - 15) * (k - 15) < 144;
            }) &&
      (spec.seriesUid = "1.2.826.0.1.3680043.2.1125.9", write("box", 20, [](int i, int j, int k) {
         return i >= 5 && i < 35 && j >= 5 && j < 35 && k > 3 && k < 16;
       }));
  if (!ok) std::fprintf(stderr, "ewa_window_fixture: cannot write %s\n", folder.c_str());
  return ok ? 0 : 1;
}
