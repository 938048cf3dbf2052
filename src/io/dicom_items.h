// Reading nested DICOM datasets (functional groups and the like) without GDCM's asserting
// attribute parsers: the first item of a sequence, the numbers of a DS element.
#pragma once

#include <gdcmDataSet.h>
#include <gdcmSequenceOfItems.h>
#include <gdcmTag.h>

#include <vector>

namespace ewa {

// The functional groups of enhanced (multi-frame) files: those all frames share, and one item a
// frame.
inline const gdcm::Tag kSharedFunctionalGroups(0x5200, 0x9229);
inline const gdcm::Tag kPerFrameFunctionalGroups(0x5200, 0x9230);

// The sequences of one read dataset, kept alive while their items' datasets are used (GDCM
// may parse a sequence's bytes into a new object that only the returned pointer holds).
class DicomItems {
 public:
  // The items of sequence `tag` in `ds` (null when absent or not a sequence).
  const gdcm::SequenceOfItems* sequence(const gdcm::DataSet& ds, const gdcm::Tag& tag);
  // The first item's dataset of sequence `tag` in `ds` (null `ds`: null), if any.
  const gdcm::DataSet* first(const gdcm::DataSet* ds, const gdcm::Tag& tag);

 private:
  std::vector<gdcm::SmartPointer<gdcm::SequenceOfItems>> held_;
};

// The numbers of element `tag` of `ds` (a DS or IS "a\b\c", padding dropped); empty when
// absent, longer than 1 KiB or not all numbers.
std::vector<double> dicomElementNumbers(const gdcm::DataSet* ds, const gdcm::Tag& tag);

}  // namespace ewa
