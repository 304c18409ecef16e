#include "command_line.hpp"

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <QTabWidget>

#include "cli_conventions.hpp"

#include "main_window.hpp"
#include "plots/plot_panel.hpp"
#include "view3d/scene_view.hpp"

namespace maris::ui {

namespace {

constexpr int kMinSide = 200, kMaxSide = 8000;  // [px] window sizes a screenshot may ask for

QString invalid(const QString& option, const QString& value, const QString& allowed) {
  return QStringLiteral("%1 %2: %3").arg(option, value, allowed);
}

// One option's value, checked; an empty error when it is fine.
QString parseValue(const QString& option, const QString& value, CommandLine& out) {
  bool ok = false;
  if (option == QLatin1String("--screenshot")) {
    out.screenshot = value;
  } else if (option == QLatin1String("--scenario")) {
    out.scenario = value;
  } else if (option == QLatin1String("--theme")) {
    if (value != QLatin1String("light") && value != QLatin1String("dark") && value != QLatin1String("system"))
      return invalid(option, value, QStringLiteral("must be one of light, dark, system"));
    out.theme = value;
  } else if (option == QLatin1String("--size")) {
    const QStringList parts = value.split(QLatin1Char('x'));
    bool ok_w = false, ok_h = false;
    const int w = parts.value(0).toInt(&ok_w), h = parts.value(1).toInt(&ok_h);
    if (parts.size() != 2 || !ok_w || !ok_h || w < kMinSide || w > kMaxSide || h < kMinSide || h > kMaxSide)
      return invalid(option, value,
                     QStringLiteral("must be WIDTHxHEIGHT in pixels, each in [%1, %2], e.g. 1600x1000").arg(kMinSide).arg(kMaxSide));
    out.width = w;
    out.height = h;
  } else if (option == QLatin1String("--frame")) {
    const int frame = value.toInt(&ok);
    if (!ok || frame < 1) return invalid(option, value, QStringLiteral("must be a frame number from 1"));
    out.frame = frame;
  } else if (option == QLatin1String("--time")) {
    const double t = value.toDouble(&ok);
    if (!ok || !std::isfinite(t)) return invalid(option, value, QStringLiteral("must be a time in seconds"));
    out.time = t;
  } else if (option == QLatin1String("--tab")) {
    out.tab = value;
  } else if (option == QLatin1String("--colormap")) {
    out.color_map = colorMapFromKey(value);
    if (!out.color_map)
      return invalid(option, value, QStringLiteral("must be one of %1").arg(colorMapKeys().join(QStringLiteral(", "))));
  }
  return {};
}

// maris's options as CLI11 reads them: strings, checked by parseValue afterwards so that a bad value's
// message names the option, the value and what is allowed.
struct Parser {
  CLI::App app{"The Maris desktop application: pick a scenario, edit its parameters, run it, and see the results\n"
               "as plots and in 3D.\n"
               "  maris [SCENARIO] [--theme NAME]\n"
               "  maris --screenshot FILE [--scenario SCENARIO] [--size WxH] [--theme NAME]\n"
               "        [--frame K | --time T] [--tab PLOT] [--colormap MAP]\n",
               "maris"};
  std::string scenario;  // the positional SCENARIO
  struct Valued {
    CLI::Option* option = nullptr;
    std::string value;
  };
  std::vector<Valued> valued;  // reserved once: CLI11 keeps pointers to the values
  CLI::Option* positional = nullptr;

  Parser() {
    cli::applyConventions(app, false);
    app.footer(cli::exitCodesHelp(false) +
               "With --screenshot also 1 for a --frame, --time or --tab the finished run does not have, and 2 for a\n"
               "scenario that cannot be opened or run.\n");
    positional = app.add_option("SCENARIO", scenario,
                                "a scenario file (*.json) or a built-in scenario's name (see `maris-cli list`)")
                     ->type_name("");
    const std::string maps = colorMapKeys().join(QStringLiteral(", ")).toStdString();
    const std::vector<std::array<std::string, 3>> options = {
        {"--theme", "NAME", "light, dark or system (the platform's palette); remembered"},
        {"--screenshot", "FILE",
         "open SCENARIO (default: the default built-in), run it to completion,\n"
         "save a PNG of the main window with its results, and exit"},
        {"--scenario", "SCENARIO", "the same as SCENARIO"},
        {"--size", "WxH",
         "window size for --screenshot in pixels (default 1600x1000; " + std::to_string(kMinSide) + " to " +
             std::to_string(kMaxSide) + ")"},
        {"--frame", "K", "3D view: show frame K (1 = the first; default: the last)"},
        {"--time", "T", "3D view: show the frame nearest to time T [s]"},
        {"--tab", "PLOT",
         "the plot tab shown: a plot's name (as in its exported file name,\n"
         "e.g. top_force) or its tab title (default: the first)"},
        {"--colormap", "MAP", "3D colour map: " + maps},
    };
    valued.reserve(options.size());
    for (const auto& [name, type, description] : options) {
      valued.push_back({});
      valued.back().option = app.add_option(name, valued.back().value, description)->type_name(type);
    }
  }
};

}  // namespace

ParsedCommandLine parseCommandLine(const QStringList& arguments) {
  ParsedCommandLine parsed;
  Parser parser;
  std::vector<std::string> args;
  for (const QString& a : arguments) args.push_back(a.toStdString());
  const cli::ParseOutcome outcome = cli::parseArguments(parser.app, args);
  parsed.exit_code = outcome.exit_code;
  parsed.output = QString::fromStdString(outcome.output);
  parsed.error = QString::fromStdString(outcome.error);
  if (outcome.exit_code) return parsed;

  CommandLine& out = parsed.options;
  auto fail = [&parsed](const QString& error) {
    parsed.error = error;
    parsed.exit_code = cli::kExitUsage;
    return parsed;
  };
  for (const auto& v : parser.valued) {
    if (v.option->count() == 0) continue;
    const QString problem = parseValue(QString::fromStdString(v.option->get_name()), QString::fromStdString(v.value), out);
    if (!problem.isEmpty()) return fail(problem);
  }
  if (parser.positional->count() > 0) {
    const QString scenario = QString::fromStdString(parser.scenario);
    if (!out.scenario.isEmpty())
      return fail(QStringLiteral("%1: only one scenario can be opened (--scenario %2 was given)").arg(scenario, out.scenario));
    out.scenario = scenario;
  }
  if (out.frame && out.time) return fail(QStringLiteral("--frame and --time: give one of them, not both"));
  const bool view_options = out.frame || out.time || !out.tab.isEmpty() || out.color_map;
  if (view_options && out.screenshot.isEmpty())
    return fail(QStringLiteral("--frame, --time, --tab and --colormap choose what a --screenshot shows: give --screenshot FILE too"));
  return parsed;
}

QString commandLineHelp() {
  Parser parser;
  return QString::fromStdString(parser.app.help());
}

QString applyViewOptions(MainWindow& window, const CommandLine& options) {
  SceneView* view = window.sceneView();
  const int frames = view->frameCount();
  if ((options.frame || options.time) && frames == 0)
    return QStringLiteral("%1: this run has no 3D view").arg(options.frame ? "--frame" : "--time");
  if (options.frame) {
    if (*options.frame > frames)
      return invalid(QStringLiteral("--frame"), QString::number(*options.frame),
                     QStringLiteral("must be in [1, %1] (this run's 3D frames)").arg(frames));
    view->setPlaying(false);
    view->setFrame(*options.frame - 1);
  }
  if (options.time) {
    const double first = view->frameTime(0), last = view->frameTime(frames - 1);
    const double slack = frames > 1 ? 0.5 * (last - first) / (frames - 1) : 0.0;  // half a frame
    if (*options.time < first - slack || *options.time > last + slack)
      return invalid(QStringLiteral("--time"), QString::number(*options.time),
                     QStringLiteral("must be in [%1, %2] s (this run's 3D frames)").arg(first).arg(last));
    int nearest = 0;
    for (int k = 1; k < frames; ++k)
      if (std::abs(view->frameTime(k) - *options.time) < std::abs(view->frameTime(nearest) - *options.time)) nearest = k;
    view->setPlaying(false);
    view->setFrame(nearest);
  }
  if (options.color_map) {
    ColorSettings settings = view->colorSettings();
    settings.map = *options.color_map;
    view->setColorSettings(settings);
  }
  if (!options.tab.isEmpty()) {
    PlotPanel* plots = window.plots();
    QStringList names;
    for (int i = 0; i < plots->count(); ++i) {
      const PlotSpec& spec = plots->view(i)->spec();
      names << QString::fromStdString(spec.name);
      if (options.tab == names.back() || options.tab == plots->tabs()->tabText(i) ||
          options.tab == plots->tabs()->tabToolTip(i)) {
        plots->tabs()->setCurrentIndex(i);
        return {};
      }
    }
    return invalid(QStringLiteral("--tab"), options.tab,
                   names.isEmpty() ? QStringLiteral("this run has no plots")
                                   : QStringLiteral("no such plot; this run's plots are %1").arg(names.join(QStringLiteral(", "))));
  }
  return {};
}

}  // namespace maris::ui
