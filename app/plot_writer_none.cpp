#include "plot_writer.hpp"

std::vector<std::filesystem::path> writePlotPngs(const std::filesystem::path&, const maris::Results&, int, char**) {
  return {};
}

std::vector<std::filesystem::path> writeStudyPngs(const std::filesystem::path&, const maris::study::CollectedStudy&,
                                                  const maris::study::StudyManifest&, int, char**) {
  return {};
}
