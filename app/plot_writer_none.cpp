#include "plot_writer.hpp"

std::vector<std::filesystem::path> writePlotPngs(const std::filesystem::path&, const maris::Results&, int, char**) {
  return {};
}

std::vector<std::filesystem::path> writeStudyPngs(const std::filesystem::path&, const std::vector<maris::study::StudyPlot>&,
                                                  int, char**) {
  return {};
}
