// PNG plots for the headless runner, rendered off-screen with the same plot code as the GUI.
#pragma once

#include <filesystem>
#include <vector>

#include "core/results.hpp"
#include "study/study_collect.hpp"

// Writes DIR/<plot name>.png for every PlotSpec; returns the files written (none when the
// build has no GUI libraries).
std::vector<std::filesystem::path> writePlotPngs(const std::filesystem::path& dir, const maris::Results& results,
                                                 int argc, char** argv);

// Writes DIR/<file stem>.png for every plot of a collected study (studyPlots: a result against a parameter,
// or a heat map); returns the files written (none without the GUI libraries).
std::vector<std::filesystem::path> writeStudyPngs(const std::filesystem::path& dir,
                                                  const maris::study::CollectedStudy& collected,
                                                  const maris::study::StudyManifest& manifest, int argc, char** argv);
