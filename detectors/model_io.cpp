// LoadDetector: reads the first line of a model file and hands it to the right class.

#include <sstream>

#include "detectors/detector.h"
#include "detectors/incipient.h"
#include "detectors/logreg.h"
#include "detectors/svm.h"
#include "detectors/text_io.h"
#include "detectors/threshold.h"

namespace tactip {

std::unique_ptr<Detector> LoadDetector(const std::string& path) {
  // Header: "tactip-detector <name> <version>".
  const std::string text = ReadText(path);
  std::istringstream in(text);
  std::string magic, name;
  in >> magic >> name;
  if (magic != "tactip-detector") {
    throw InputError("model '" + path + "': not a tactip detector model (first word '" + magic + "')");
  }
  if (name == "threshold") return ThresholdDetector::Load(path);
  if (name == "incipient") return IncipientDetector::Load(path);
  if (name == "svm-linear" || name == "svm-rbf") return SvmDetector::Load(path);
  if (name == "logreg") return LogRegDetector::Load(path);
  throw InputError("model '" + path + "': unknown detector '" + name + "'");
}

}  // namespace tactip
