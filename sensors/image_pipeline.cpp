#include "sensors/image_pipeline.h"

namespace tactip {

SensorImagePipeline::SensorImagePipeline(const TactileImageConfig& cfg, const CameraConfig& camera,
                                         std::uint64_t noise_seed)
    : renderer_(cfg, camera, noise_seed), detector_(cfg), gate_px_(cfg.gate_px) {}

const ImageReading& SensorImagePipeline::Capture(const std::vector<float>& clean_px, const std::vector<float>& pos_m) {
  // Render the frame and keep it compressed.
  const cv::Mat& image = renderer_.Render(clean_px, pos_m);
  reading_.image = CompressFrame(image.data, image.total());
  // The tracker starts at the first frame's projected positions.
  if (!tracker_) {
    std::vector<cv::Point2f> start;
    for (size_t i = 0; i + 1 < clean_px.size(); i += 2) start.emplace_back(clean_px[i], clean_px[i + 1]);
    tracker_.emplace(std::move(start), gate_px_);
  }
  // Blobs, then each pin's nearest blob.
  tracker_->Update(detector_.Detect(image));
  reading_.detected_px.clear();
  for (const cv::Point2f& p : tracker_->positions()) {
    reading_.detected_px.push_back(p.x);
    reading_.detected_px.push_back(p.y);
  }
  reading_.detected_valid = tracker_->valid();
  return reading_;
}

}  // namespace tactip
