// The optional image arrays of a dataset: written as one deflate chunk per frame, read back
// when present, absent from runs recorded without images.

#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "sensors/dataset.h"
#include "input_error.h"
#include "run_records.h"

namespace tactip {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 8, kHeight = 5;  // a small frame

// Run `index` of `t` frames of `n` pins with images: frame f's pixel k is f + 3k (mod 256).
RunRecord RunWithImages(int index, int t, int n) {
  RunRecord run = MakeRun(index, t, n);
  SensorRecord& s = run.sensors[0];
  s.image_width = kWidth;
  s.image_height = kHeight;
  for (int f = 0; f < t; ++f) {
    std::vector<std::uint8_t> pixels(kWidth * kHeight);
    for (size_t k = 0; k < pixels.size(); ++k) pixels[k] = static_cast<std::uint8_t>(f + 3 * k);
    s.images.push_back(CompressFrame(pixels.data(), pixels.size()));
  }
  for (size_t k = 0; k < s.pos_px.size(); ++k) s.detected_px.push_back(s.pos_px[k] + 0.125f);
  for (size_t k = 0; k < s.valid.size(); ++k) s.detected_valid.push_back(k % 4 == 0 ? 0 : 1);
  return run;
}

std::string TempPath(const std::string& name) {
  return (fs::temp_directory_path() / ("tactip_dataset_images_" + std::to_string(::getpid()) + "_" + name)).string();
}

TEST(DatasetImagesTest, ImagesAndDetectedPinsRoundTripFrameByFrame) {
  const std::string path = TempPath("a.h5");
  const RunRecord run = RunWithImages(2, 4, 3);
  {
    DatasetWriter w(path, DatasetHeader{});
    w.WriteRun(run);
    w.Commit();
  }
  const RunRecord back = DatasetReader(path).ReadRun(2);
  fs::remove(path);
  const SensorRecord& s = back.sensors.at(0);
  EXPECT_EQ(s.image_width, kWidth);
  EXPECT_EQ(s.image_height, kHeight);
  ASSERT_EQ(s.images.size(), 4u);
  for (size_t f = 0; f < 4; ++f) {
    EXPECT_EQ(DecompressFrame(s.images[f], kWidth * kHeight),
              DecompressFrame(run.sensors[0].images[f], kWidth * kHeight));
  }
  EXPECT_EQ(s.detected_px, run.sensors[0].detected_px);
  EXPECT_EQ(s.detected_valid, run.sensors[0].detected_valid);
  ExpectSameRun(back, run);
}

TEST(DatasetImagesTest, TheImageArrayIsChunkedOneFramePerChunkUnderDeflate) {
  const std::string path = TempPath("b.h5");
  {
    DatasetWriter w(path, DatasetHeader{});
    w.WriteRun(RunWithImages(0, 3, 2));
    w.Commit();
  }
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const hid_t dset = H5Dopen2(file, "/runs/run_0000/sensors/tactip/images", H5P_DEFAULT);
  ASSERT_GE(dset, 0);
  const hid_t dcpl = H5Dget_create_plist(dset);
  hsize_t chunk[3] = {0, 0, 0};
  EXPECT_EQ(H5Pget_chunk(dcpl, 3, chunk), 3);
  EXPECT_EQ(chunk[0], 1u);
  EXPECT_EQ(chunk[1], static_cast<hsize_t>(kHeight));
  EXPECT_EQ(chunk[2], static_cast<hsize_t>(kWidth));
  EXPECT_EQ(H5Pget_filter2(dcpl, 0, nullptr, nullptr, nullptr, 0, nullptr, nullptr), H5Z_FILTER_DEFLATE);
  // HDF5 itself decodes the chunks to the pixels written.
  std::vector<std::uint8_t> all(3 * kWidth * kHeight);
  EXPECT_GE(H5Dread(dset, H5T_NATIVE_UINT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, all.data()), 0);
  EXPECT_EQ(all[kWidth * kHeight + 2], 1 + 3 * 2);
  H5Pclose(dcpl);
  H5Dclose(dset);
  H5Fclose(file);
  fs::remove(path);
}

TEST(DatasetImagesTest, ARunWithoutImagesReadsWithoutThem) {
  const std::string path = TempPath("c.h5");
  {
    DatasetWriter w(path, DatasetHeader{});
    w.WriteRun(MakeRun(0, 3, 2));
    w.Commit();
  }
  const RunRecord back = DatasetReader(path).ReadRun(0);
  fs::remove(path);
  EXPECT_TRUE(back.sensors.at(0).images.empty());
  EXPECT_TRUE(back.sensors.at(0).detected_px.empty());
  EXPECT_TRUE(back.sensors.at(0).detected_valid.empty());
}

TEST(DatasetImagesTest, CheckShapesRefusesImagesOfAnotherFrameCount) {
  RunRecord run = RunWithImages(0, 3, 2);
  run.sensors[0].images.pop_back();
  EXPECT_THROW(run.CheckShapes(), std::logic_error);
}

TEST(DatasetImagesTest, ImagesNotStoredOneChunkPerFrameAreRefusedNamingTheArray) {
  const std::string path = TempPath("d.h5");
  {
    DatasetWriter w(path, DatasetHeader{});
    w.WriteRun(RunWithImages(0, 3, 2));
    w.Commit();
  }
  {
    // Replace the images by a contiguous (unchunked) array of the same shape.
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    const hid_t sensor = H5Gopen2(file, "/runs/run_0000/sensors/tactip", H5P_DEFAULT);
    H5Ldelete(sensor, "images", H5P_DEFAULT);
    const hsize_t shape[3] = {3, kHeight, kWidth};
    const hid_t space = H5Screate_simple(3, shape, nullptr);
    const hid_t dset = H5Dcreate2(sensor, "images", H5T_STD_U8LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dclose(dset);
    H5Sclose(space);
    H5Gclose(sensor);
    H5Fclose(file);
  }
  const std::string message = InputErrorOf([&] { DatasetReader(path).ReadRun(0); });
  fs::remove(path);
  EXPECT_EQ(message, "dataset '" + path +
                         "': run_0000/sensors/tactip/images is not stored one deflate-compressed chunk per frame "
                         "(chunks (1, 5, 8), gzip)");
}

}  // namespace
}  // namespace tactip
