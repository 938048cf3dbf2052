// Fuzz target: transfer-function JSON. A parsed function must validate, bake to finite
// samples and read back equal from the text saveTransferFunction would write.
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/transfer_function.h"
#include "fuzz_case.h"
#include "io/transfer_function_io.h"

EWA_FUZZ_TARGET(tf_json) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  ewa::TransferFunction tf;
  try {
    tf = ewa::parseTransferFunctionJson(text, "fuzz.tf.json");
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EWA_FUZZ_CHECK(message.rfind("fuzz.tf.json: ", 0) == 0);
    EWA_FUZZ_CHECK(message.find('\n') == std::string::npos);
    return;
  }
  tf.validate();
  for (const glm::vec4& s : tf.bake(-1.0, 1000.0, 64)) {
    for (int c = 0; c < 4; ++c) EWA_FUZZ_CHECK(std::isfinite(s[c]) && s[c] >= 0.0f);
  }
  EWA_FUZZ_CHECK(tf.alphaAt(std::nan("")) == 0.0);
  const ewa::TransferFunction again =
      ewa::parseTransferFunctionJson(ewa::transferFunctionToJson(tf), "round trip");
  EWA_FUZZ_CHECK(again == tf);
}
