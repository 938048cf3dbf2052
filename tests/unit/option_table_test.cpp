// The option table against the parser it feeds: every row an option, grouped --help, and each
// default the table (and so --help and docs/user/options.md) states is the one the parse keeps.
#include "app/option_table.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <vector>

#include "app/options.h"
#include "render/renderer.h"

namespace ewa {
namespace {

// What a parse sets, as text: two parses that agree print the same.
std::string settingsText(const Options& o) {
  const RenderSettings& r = o.render;
  std::ostringstream out;
  out << o.file << '|' << o.synthetic << '|' << o.output << '|' << o.turntable << '|' << o.fps
      << '|' << o.tour << '|' << o.width << 'x' << o.height << '|' << o.cameraViewAngle << '|'
      << o.orthographic << o.axes << o.stats << o.info << o.watch << '|' << o.tfFile << '|'
      << o.backend << '|' << o.load.frame << ',' << o.load.channel << ',' << o.overlay << '|'
      << o.rawSpacing << o.rawEndian << '|' << int(r.renderer) << int(r.filter) << int(r.mode)
      << '|' << r.cutoff << ',' << r.kernelWidth << ',' << r.lowPass << ',' << r.depthCutoff << ','
      << r.slabThickness << '|' << r.background.x << r.background.y << r.background.z << '|'
      << int(r.order) << ',' << r.terminationOpacity << ',' << int(r.occlusionCulling) << '|'
      << int(r.xrayMap) << ',' << r.xrayScale << '|' << r.lighting.enabled << ','
      << r.lighting.ambient << ',' << r.lighting.diffuse << ',' << r.lighting.specular << ','
      << r.lighting.shininess << '|' << int(r.classification.mode) << ','
      << int(r.classification.gradient) << ',' << r.classification.prefilter << ','
      << r.classification.minGradient << ',' << int(r.classification.surface) << '|'
      << r.slabPreintegration << ',' << r.slabSamples << ',' << r.slabPasses << ','
      << int(r.slabPrecision) << ',' << int(r.postNormals) << ',' << int(r.splatter) << ','
      << r.coarseSlabs << ',' << r.surfaceOpacity << '|' << r.shearWarp.preintegrated
      << int(r.shearWarp.lookup) << r.shearWarp.opacityCorrection << int(r.shearWarp.buffers) << ','
      << r.shearWarp.intermediateScale << '|' << r.clip.active();
  return out.str();
}

Options parsed(const std::vector<std::string>& words) {
  std::vector<const char*> argv{"ewaview"};
  for (const std::string& w : words) argv.push_back(w.c_str());
  Options options;
  const ParseResult result = parseCommandLine(int(argv.size()), argv.data(), &options);
  EXPECT_TRUE(result.run) << (words.empty() ? "" : words[0]);
  return options;
}

TEST(OptionTable, EveryRowIsAnOptionOfTheParser) {
  const std::string help = commandLineHelp();
  for (const OptionSpec& spec : optionTable()) {
    if (spec.name == "file") continue;  // the positional, under "Positionals"
    EXPECT_NE(help.find(spec.name), std::string::npos) << spec.name << " is not in --help";
  }
}

TEST(OptionTable, HelpListsTheGroupsInOrder) {
  const std::string help = commandLineHelp();
  size_t at = 0;
  for (OptionGroup group : kOptionGroups) {
    const size_t found = help.find(std::string("\n") + optionGroupTitle(group) + ":", at);
    ASSERT_NE(found, std::string::npos) << optionGroupTitle(group);
    at = found;
  }
  // --tf among the transfer function's options, not after the renderer's internals.
  EXPECT_LT(help.find("--tf "), help.find("Rendering:"));
  // The --synthetic line names every synthetic volume the parser makes.
  for (const char* spec :
       {"marschner-lobb[:N]", "sphere[:N]", "box[:N]", "checkerboard[:S]", "zebra[:RATIO]"})
    EXPECT_NE(help.find(spec), std::string::npos) << spec;
}

TEST(OptionTable, DefaultsAreTheSettingsDefaults) {
  EXPECT_EQ(optionSpec("--kernel-width").defaultText, numberText(RenderSettings{}.kernelWidth));
  EXPECT_EQ(optionSpec("--cutoff").defaultText, numberText(RenderSettings{}.cutoff));
  EXPECT_EQ(optionSpec("--filter").defaultText, filterModeName(RenderSettings{}.filter));
  EXPECT_NE(optionSpec("--kernel-width")
                .description()
                .find("(default " + numberText(RenderSettings{}.kernelWidth) + ")"),
            std::string::npos);
}

// Giving an option its stated default changes nothing: the table's default is the parser's.
TEST(OptionTable, GivingTheDefaultChangesNothing) {
  if (std::getenv("EWAVIEW_BACKEND")) GTEST_SKIP() << "EWAVIEW_BACKEND names another default";
  const std::string none = settingsText(parsed({}));
  for (const OptionSpec& spec : optionTable()) {
    if (spec.defaultText.empty() || spec.name.rfind("--raw-", 0) == 0) continue;  // --raw-dims
    if (spec.name == "--surface-min-gradient") continue;                          // below
    EXPECT_EQ(settingsText(parsed({spec.name + "=" + spec.defaultText})), none)
        << spec.name << "=" << spec.defaultText;
  }
  // Options that need another: the same with and without them.
  const std::string surface = "--surface-opacity-threshold=0.5";
  EXPECT_EQ(settingsText(parsed({surface, "--surface-min-gradient=" +
                                              optionSpec("--surface-min-gradient").defaultText})),
            settingsText(parsed({surface})));
  const std::vector<std::string> raw = {"volume.raw", "--raw-dims=4,4,4", "--raw-type=uint8"};
  for (const char* name : {"--raw-spacing", "--raw-endian"}) {
    std::vector<std::string> words = raw;
    words.push_back(std::string(name) + "=" + optionSpec(name).defaultText);
    EXPECT_EQ(settingsText(parsed(words)), settingsText(parsed(raw))) << name;
  }
}

TEST(OptionTable, ChoicesAreAcceptedAndOthersRefused) {
  for (const OptionSpec& spec : optionTable())
    for (const std::string& choice : spec.choices) parsed({spec.name + "=" + choice});
  std::vector<const char*> argv{"ewaview", "--filter=gauss"};
  Options options;
  testing::internal::CaptureStderr();
  EXPECT_EQ(parseCommandLine(2, argv.data(), &options).exitCode, 2);
  testing::internal::GetCapturedStderr();
}

TEST(OptionTable, PythonKeywords) {
  ASSERT_NE(optionForKeyword("kernel_width"), nullptr);
  EXPECT_TRUE(optionForKeyword("kernel_width")->python);
  for (const char* notInPython : {"output", "turntable", "help", "version", "file", "watch"}) {
    ASSERT_NE(optionForKeyword(notInPython), nullptr) << notInPython;
    EXPECT_FALSE(optionForKeyword(notInPython)->python) << notInPython;
  }
  EXPECT_EQ(optionForKeyword("no_such_option"), nullptr);
}

TEST(OptionTable, UnknownNameIsAnError) {
  EXPECT_THROW(optionSpec("--no-such-option"), std::logic_error);
}

}  // namespace
}  // namespace ewa
