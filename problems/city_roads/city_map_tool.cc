// Writes the shipped city-roads map (DrawCityMap) as a 1-bit PNG and its
// frame sidecar beside it: city_map PATH.png (writes PATH.png and PATH.yaml).
#include <iostream>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "problems/city_roads/city_roads.h"
#include "problems/marina_sonar/marina_map.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: city_map OUT.png\n";
    return 2;
  }
  const std::string path = argv[1];
  const std::vector<int> options = {cv::IMWRITE_PNG_BILEVEL, 1, cv::IMWRITE_PNG_COMPRESSION, 9};
  if (!cv::imwrite(path, icp::DrawCityMap(), options)) {
    std::cerr << path << ": cannot write\n";
    return 1;
  }
  icp::WriteMapFrame(icp::CityMapFrame(), icp::MapFramePath(path),
                     "frame of the city-roads map: world (x east, y north, m) of the image's "
                     "lower-left corner and the side of a pixel; written by city_map");
  return 0;
}
