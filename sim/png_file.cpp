#include "sim/png_file.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <fmt/format.h>

#include "sim/config.h"
#include "sim/base/files.h"

namespace tactip {

void SavePng(const RgbImage& image, const std::string& path) {
  const auto bytes = 3 * static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
  if (image.width <= 0 || image.height <= 0 || image.rgb.size() != bytes) {
    throw InputError(fmt::format("{}: cannot write an empty or malformed image", path));
  }
  // OpenCV stores colour images as BGR.
  const cv::Mat rgb(image.height, image.width, CV_8UC3, const_cast<std::uint8_t*>(image.rgb.data()));
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", bgr, png)) throw InputError(fmt::format("{}: PNG encoding failed", path));
  WriteFileAtomic(path, std::string(png.begin(), png.end()));
}

RgbImage ReadPng(const std::string& path) {
  const cv::Mat bgr = cv::imread(path, cv::IMREAD_COLOR);
  if (bgr.empty()) throw InputError(fmt::format("{}: missing or not an image file", path));
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  RgbImage image;
  image.width = rgb.cols;
  image.height = rgb.rows;
  image.rgb.assign(rgb.data, rgb.data + rgb.total() * rgb.elemSize());
  return image;
}

}  // namespace tactip
