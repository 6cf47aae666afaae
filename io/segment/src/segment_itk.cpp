// The island, median and closing/opening operations with ITK's filters (Debian's
// libinsighttoolkit5): their connected components, relabelling by size, binary median and
// binary morphology with a ball are sound and fast enough (segment_bench measures them).
#include "segment_itk.h"

#include <algorithm>
#include <cstring>

#include <itkBinaryBallStructuringElement.h>
#include <itkBinaryFillholeImageFilter.h>
#include <itkBinaryMedianImageFilter.h>
#include <itkBinaryMorphologicalClosingImageFilter.h>
#include <itkBinaryMorphologicalOpeningImageFilter.h>
#include <itkConnectedComponentImageFilter.h>
#include <itkImage.h>
#include <itkImageRegionConstIterator.h>
#include <itkRelabelComponentImageFilter.h>

namespace voxray::itk_ops {
namespace {

using MaskImage = itk::Image<uint8_t, 3>;
using LabelImage = itk::Image<uint32_t, 3>;

MaskImage::Pointer toImage(const Block& b) {
  auto image = MaskImage::New();
  MaskImage::SizeType size;
  for (int a = 0; a < 3; ++a) size[a] = itk::SizeValueType(b.dims[a]);
  image->SetRegions(MaskImage::RegionType(size));
  MaskImage::SpacingType spacing;
  for (int a = 0; a < 3; ++a) spacing[a] = b.spacingMm[a];
  image->SetSpacing(spacing);
  image->Allocate();
  std::memcpy(image->GetBufferPointer(), b.voxels.data(), b.voxels.size());
  return image;
}

void fromImage(const MaskImage* image, Block& b) {
  std::memcpy(b.voxels.data(), image->GetBufferPointer(), b.voxels.size());
}

using Ball = itk::BinaryBallStructuringElement<uint8_t, 3>;

Ball ball(glm::ivec3 radius) {
  Ball element;
  Ball::SizeType r;
  for (int a = 0; a < 3; ++a) r[a] = itk::SizeValueType(std::max(radius[a], 0));
  element.SetRadius(r);
  element.CreateStructuringElement();
  return element;
}

}  // namespace

Islands islands(const Block& b, bool fullyConnected) {
  auto components = itk::ConnectedComponentImageFilter<MaskImage, LabelImage>::New();
  components->SetInput(toImage(b));
  components->SetFullyConnected(fullyConnected);
  auto relabel = itk::RelabelComponentImageFilter<LabelImage, LabelImage>::New();
  relabel->SetInput(components->GetOutput());
  relabel->Update();
  Islands out;
  const auto* labels = relabel->GetOutput()->GetBufferPointer();
  out.labels.assign(labels, labels + b.voxels.size());
  for (auto n : relabel->GetSizeOfObjectsInPixels()) out.sizes.push_back(uint64_t(n));
  return out;
}

void median(Block& b, glm::ivec3 radius) {
  auto filter = itk::BinaryMedianImageFilter<MaskImage, MaskImage>::New();
  filter->SetInput(toImage(b));
  MaskImage::SizeType r;
  for (int a = 0; a < 3; ++a) r[a] = itk::SizeValueType(std::max(radius[a], 0));
  filter->SetRadius(r);
  filter->SetForegroundValue(1);
  filter->SetBackgroundValue(0);
  filter->Update();
  fromImage(filter->GetOutput(), b);
}

void closing(Block& b, glm::ivec3 radius) {
  auto filter = itk::BinaryMorphologicalClosingImageFilter<MaskImage, MaskImage, Ball>::New();
  filter->SetInput(toImage(b));
  filter->SetKernel(ball(radius));
  filter->SetForegroundValue(1);
  // The block carries a margin of the radius (segment_ops.cpp), so no safe border is needed.
  filter->SetSafeBorder(false);
  filter->Update();
  fromImage(filter->GetOutput(), b);
}

void opening(Block& b, glm::ivec3 radius) {
  auto filter = itk::BinaryMorphologicalOpeningImageFilter<MaskImage, MaskImage, Ball>::New();
  filter->SetInput(toImage(b));
  filter->SetKernel(ball(radius));
  filter->SetForegroundValue(1);
  filter->SetBackgroundValue(0);
  filter->Update();
  fromImage(filter->GetOutput(), b);
}

void fillHoles(Block& b) {
  auto filter = itk::BinaryFillholeImageFilter<MaskImage>::New();
  filter->SetInput(toImage(b));
  filter->SetForegroundValue(1);
  filter->SetFullyConnected(false);
  filter->Update();
  fromImage(filter->GetOutput(), b);
}

}  // namespace voxray::itk_ops
