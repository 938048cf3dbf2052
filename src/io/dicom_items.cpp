// DicomItems and dicomElementNumbers: nested DICOM values read with ewaview's strict parsing.
#include "io/dicom_items.h"

#include <string>

#include "io/dicom_series.h"

namespace ewa {

const gdcm::SequenceOfItems* DicomItems::sequence(const gdcm::DataSet& ds, const gdcm::Tag& tag) {
  if (!ds.FindDataElement(tag)) return nullptr;
  gdcm::SmartPointer<gdcm::SequenceOfItems> sq = ds.GetDataElement(tag).GetValueAsSQ();
  if (!sq) return nullptr;
  held_.push_back(sq);
  return sq.GetPointer();
}

const gdcm::DataSet* DicomItems::first(const gdcm::DataSet* ds, const gdcm::Tag& tag) {
  const gdcm::SequenceOfItems* sq = ds ? sequence(*ds, tag) : nullptr;
  return sq && sq->GetNumberOfItems() > 0 ? &sq->GetItem(1).GetNestedDataSet() : nullptr;
}

std::vector<double> dicomElementNumbers(const gdcm::DataSet* ds, const gdcm::Tag& tag) {
  if (!ds || !ds->FindDataElement(tag)) return {};
  const gdcm::ByteValue* bytes = ds->GetDataElement(tag).GetByteValue();
  if (!bytes || bytes->GetLength() == 0 || bytes->GetLength() > 1024) return {};
  std::string text(bytes->GetPointer(), bytes->GetLength());
  while (!text.empty() && (text.back() == '\0' || text.back() == ' ')) text.pop_back();
  return dicomNumbers(text.c_str());
}

}  // namespace ewa
