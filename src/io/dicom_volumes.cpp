// DICOM series holding several volumes at the same positions: grouped by position, one picked.
#include "io/dicom_volumes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>

#include "io/load_failure.h"

namespace ewa {

namespace {

constexpr double kSamePosition = 1e-4;  // mm along the normal: repeated positions are equal text

// --frame against the series' volumes (1 when it holds one).
void checkVolume(const std::string& path, int volume, size_t count) {
  checkFrame(path, volume, int64_t(count), "the series has", "volume", " at its positions");
}

// The number each image states for its place in the acquisition: its InstanceNumber, or a
// frame's index in its multi-frame file. Empty when one is unnumbered or two are alike: then
// only file names would order them, which say nothing of the volumes.
std::vector<int64_t> imageNumbers(const std::vector<DicomSlice>& slices) {
  // An enhanced file's frames (dicomFrameSlices): one file, each frame a slice of its own.
  const bool frames = std::all_of(slices.begin(), slices.end(), [&](const DicomSlice& s) {
    return s.file == slices.front().file;
  });
  std::vector<int64_t> numbers;
  for (const DicomSlice& s : slices) {
    if (!frames && (s.frames != 1 || s.instance == 0)) return {};
    numbers.push_back(frames ? s.frame : s.instance);
  }
  std::vector<int64_t> sorted = numbers;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return {};
  return numbers;
}

// Where positions hold unequal numbers of slices (a file missing, a scan cut short), the
// volumes are told apart by the images' numbers, in one of the two ways scanners number them.
// One volume after another: in number order, a volume ends where the positions step back
// against the direction they run in (that of most steps). True, with `volumeOf` filled, when
// that gives `volumes` volumes (the most any position holds); numbered slice by slice, it would
// give about positions x volumes.
bool volumeMajor(const std::vector<int64_t>& numbers, const std::vector<int>& position,
                 size_t volumes, std::vector<size_t>& volumeOf) {
  std::vector<size_t> order(numbers.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return numbers[a] < numbers[b]; });
  long rising = 0;
  for (size_t n = 1; n < order.size(); ++n) {
    const int step = position[order[n]] - position[order[n - 1]];
    rising += step > 0 ? 1 : step < 0 ? -1 : 0;
  }
  if (rising == 0) return false;
  size_t band = 0;
  for (size_t n = 0; n < order.size(); ++n) {
    const size_t i = order[n];
    if (n > 0) {
      const long step = long(position[i]) - long(position[order[n - 1]]);
      if ((rising > 0 ? step <= 0 : step >= 0) && ++band == volumes) return false;
    }
    volumeOf[i] = band;
  }
  return band + 1 == volumes;
}

// Slice by slice: each position's images a block of `volumes` consecutive numbers, the blocks
// one after another (position p's after the block before it in number order), so that an image
// is volume (number - the block's first number). The blocks' starts are `volumes` apart from the
// first, which a missing image cannot hide unless every block lacks its first. True, with
// `volumeOf` filled, when every image falls inside its block; numbered one volume after another,
// the positions' numbers interleave and it is false.
bool positionMajor(const std::vector<int64_t>& numbers, const std::vector<int>& position,
                   size_t positions, size_t volumes, std::vector<size_t>& volumeOf) {
  std::vector<int64_t> lo(positions, INT64_MAX), hi(positions, INT64_MIN);
  for (size_t i = 0; i < numbers.size(); ++i) {
    const size_t p = size_t(position[i]);
    lo[p] = std::min(lo[p], numbers[i]);
    hi[p] = std::max(hi[p], numbers[i]);
  }
  std::vector<size_t> blocks(positions);  // positions in the order of their numbers
  for (size_t p = 0; p < positions; ++p) blocks[p] = p;
  std::sort(blocks.begin(), blocks.end(), [&](size_t a, size_t b) { return lo[a] < lo[b]; });
  std::vector<int64_t> rank(positions);
  int64_t first = INT64_MAX;  // the first block's start: the least of lo - rank x volumes
  for (size_t r = 0; r < positions; ++r) {
    const size_t p = blocks[r];
    if (r > 0 && lo[p] <= hi[blocks[r - 1]]) return false;  // interleaved
    rank[p] = int64_t(r);
    first = std::min(first, lo[p] - int64_t(r) * int64_t(volumes));
  }
  for (size_t i = 0; i < numbers.size(); ++i) {
    const int64_t slot = numbers[i] - first - rank[size_t(position[i])] * int64_t(volumes);
    if (slot < 0 || slot >= int64_t(volumes)) return false;
    volumeOf[i] = size_t(slot);
  }
  return true;
}

}  // namespace

std::vector<DicomSlice> selectDicomVolume(const std::string& path, std::vector<DicomSlice> slices,
                                          int volume, std::vector<std::string>& notes, int* count) {
  if (count) *count = 1;
  const bool placed =
      slices.size() > 1 && std::all_of(slices.begin(), slices.end(), [&](const DicomSlice& s) {
        return s.hasPosition && s.hasOrientation && sameDicomOrientation(s, slices.front());
      });
  if (!placed) {
    checkVolume(path, volume, 1);
    return slices;
  }
  const glm::dvec3 normal = dicomSliceNormal(slices.front().orientation);
  auto along = [&](const DicomSlice& s) { return glm::dot(s.position, normal); };
  // By position, and at each position by InstanceNumber, frame and file: the volumes' order.
  std::stable_sort(slices.begin(), slices.end(), [&](const DicomSlice& a, const DicomSlice& b) {
    const double da = along(a), db = along(b);
    if (std::fabs(da - db) > kSamePosition) return da < db;
    if (a.instance != b.instance) return a.instance < b.instance;
    if (a.frame != b.frame) return a.frame < b.frame;
    return a.file < b.file;
  });
  std::vector<size_t> starts{0};  // where each position's run begins
  for (size_t i = 1; i < slices.size(); ++i)
    if (std::fabs(along(slices[i]) - along(slices[i - 1])) > kSamePosition) starts.push_back(i);
  const size_t positions = starts.size();
  starts.push_back(slices.size());
  size_t fewest = slices.size(), most = 0;
  for (size_t p = 0; p < positions; ++p) {
    fewest = std::min(fewest, starts[p + 1] - starts[p]);
    most = std::max(most, starts[p + 1] - starts[p]);
  }
  if (positions < 2 || most == 1) {  // one place (a cine), or one volume
    checkVolume(path, volume, 1);
    return slices;
  }
  std::vector<int> position(slices.size());  // each slice's position index
  for (size_t p = 0; p < positions; ++p)
    std::fill(position.begin() + starts[p], position.begin() + starts[p + 1], int(p));
  std::vector<size_t> volumeOf(slices.size());  // each slice's volume
  if (fewest == most) {
    for (size_t p = 0; p < positions; ++p)
      for (size_t i = starts[p]; i < starts[p + 1]; ++i) volumeOf[i] = i - starts[p];
  } else if (const std::vector<int64_t> numbers = imageNumbers(slices);
             numbers.empty() || (!volumeMajor(numbers, position, most, volumeOf) &&
                                 !positionMajor(numbers, position, positions, most, volumeOf))) {
    size_t p = 0;  // a position holding the most, whose files are named
    while (starts[p + 1] - starts[p] != most) ++p;
    failLoad(path, std::to_string(positions) + " slice positions holding " +
                       std::to_string(fewest) + " to " + std::to_string(most) + " slices each (" +
                       slices[starts[p]].file + " and " + slices[starts[p] + 1].file +
                       " share one position): several volumes in the series, unevenly, and their "
                       "InstanceNumbers do not tell them apart");
  }
  checkVolume(path, volume, most);
  if (count) *count = int(most);
  std::vector<DicomSlice> picked;  // in position order, as slices are
  std::vector<size_t> held(most, 0);
  for (size_t i = 0; i < slices.size(); ++i) {
    ++held[volumeOf[i]];
    if (volumeOf[i] == size_t(volume)) picked.push_back(slices[i]);
  }
  std::string note = std::to_string(most) + " volumes at the same " + std::to_string(positions) +
                     " positions (diffusion directions, echoes or time points): volume " +
                     std::to_string(volume) + " open (--frame N opens another, 0 to " +
                     std::to_string(most - 1) + ")";
  std::string shortOnes;
  for (size_t v = 0; v < most; ++v)
    if (held[v] < positions)
      shortOnes += (shortOnes.empty() ? "" : ", ") + std::to_string(v) + " (" +
                   std::to_string(held[v]) + ")";
  if (!shortOnes.empty())
    note +=
        "; volumes short of slices, by InstanceNumber (an interrupted scan? a missing file?), "
        "with the positions each holds: " +
        shortOnes;
  notes.push_back(note);
  return picked;
}

std::optional<glm::dvec3> stackOnePosition(std::vector<DicomSlice>& slices,
                                           std::vector<std::string>& notes) {
  if (slices.size() < 2) return std::nullopt;
  for (const DicomSlice& s : slices)
    if (!s.hasPosition || !s.hasOrientation || s.frames != 1 ||
        !sameDicomOrientation(s, slices.front()) ||
        glm::length(s.position - slices.front().position) > kSamePosition)
      return std::nullopt;
  std::stable_sort(slices.begin(), slices.end(), [](const DicomSlice& a, const DicomSlice& b) {
    return a.instance != b.instance ? a.instance < b.instance : a.file < b.file;
  });
  notes.push_back(std::to_string(slices.size()) +
                  " images at one position (a cine or a time series): stacked in "
                  "InstanceNumber order, 1 apart");
  return dicomSliceNormal(slices.front().orientation);
}

}  // namespace ewa
