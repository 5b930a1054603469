// Loading descriptor plugins: a good one, and each way a load fails with its own message.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "descriptors/descriptor_registry.hpp"
#include "descriptors/plugins/plugin_compatibility.hpp"
#include "descriptors/plugins/plugin_loader.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

// The message of the std::invalid_argument that loading `path` throws ("" when it loads).
std::string load_error(const fs::path& path) {
  try {
    load_descriptor_plugin(path);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

TEST(PluginLoader, LoadsAPluginIntoTheGlobalRegistryOnce) {
  const LoadedPlugin& plugin = load_descriptor_plugin(PROBE_PLUGIN_PATH);
  EXPECT_EQ(plugin.path, fs::canonical(PROBE_PLUGIN_PATH));
  ASSERT_EQ(plugin.descriptors, std::vector<std::string>{"plugin_probe"});
  const DescriptorInfo& info = DescriptorRegistry::global().info("plugin_probe");
  EXPECT_EQ(info.plugin_path, fs::canonical(PROBE_PLUGIN_PATH).string());
  EXPECT_EQ(origin_of(info), "plugin " + info.plugin_path);
  EXPECT_EQ(origin_of(DescriptorRegistry::global().info("referee")), "built-in");
  // The build identity names the file, its size and its modification time.
  EXPECT_CONTAINS(info.plugin_build, info.plugin_path);
  EXPECT_CONTAINS(info.plugin_build, std::to_string(fs::file_size(PROBE_PLUGIN_PATH)) + " bytes");

  // The same file again, even by another spelling of its path, is the same plugin, not a
  // duplicate registration.
  const fs::path other_spelling =
      fs::path(PROBE_PLUGIN_PATH).parent_path() / "." / fs::path(PROBE_PLUGIN_PATH).filename();
  EXPECT_EQ(&load_descriptor_plugin(other_spelling), &plugin);
  std::size_t probes = 0;
  for (const auto& loaded : loaded_descriptor_plugins()) probes += loaded.path == plugin.path;
  EXPECT_EQ(probes, 1u);
}

TEST(PluginLoader, PluginDescriptorsExtractThroughTheHost) {
  load_descriptor_plugin(PROBE_PLUGIN_PATH);
  const DescriptorInstance instance =
      DescriptorRegistry::global().create("plugin_probe", nlohmann::json::object());
  // 2 x 2 scan 0, 10, 20, 50: mean 80 / 4 = 20.
  PolarImage scan;
  scan.power = ByteImage(2, 2);
  scan.power(0, 1) = 10;
  scan.power(1, 0) = 20;
  scan.power(1, 1) = 50;
  const DescriptorValue value = instance.descriptor->extract(scan);
  ASSERT_EQ(value.values.size(), 1u);
  EXPECT_FLOAT_EQ(value.values[0], 20.0f);
  EXPECT_EQ(instance.id, "plugin_probe");
}

TEST(PluginLoader, ExceptionsCrossThePluginBoundaryAsTheirOwnTypes) {
  load_descriptor_plugin(PROBE_PLUGIN_PATH);
  PolarImage scan;
  scan.power = ByteImage(2, 2, 1);
  const auto failing =
      DescriptorRegistry::global().create_from_id("plugin_probe:fail=invalid_argument");
  EXPECT_THROW(failing.descriptor->extract(scan), std::invalid_argument);
  // A radarpr exception type, whose typeinfo the host and the plugin must share.
  const auto parameter_error =
      DescriptorRegistry::global().create_from_id("plugin_probe:fail=parameter_error");
  try {
    parameter_error.descriptor->extract(scan);
    ADD_FAILURE() << "extract did not throw";
  } catch (const ParameterError& error) {
    EXPECT_EQ(error.parameter(), "fail");
  }
  // The host's checks apply to plugin parameters too.
  EXPECT_THROW(DescriptorRegistry::global().create_from_id("plugin_probe:fail=maybe"),
               ParameterError);
}

TEST(PluginLoader, RefusesAMissingFile) {
  const std::string error = load_error("/nonexistent/libnothing.so");
  EXPECT_CONTAINS(error, "plugin /nonexistent/libnothing.so: file not found");
}

TEST(PluginLoader, RefusesAFileThatIsNotASharedLibrary) {
  const fs::path text = fs::path(::testing::TempDir()) / "radarpr_not_a_library.so";
  std::ofstream(text) << "this is text, not ELF\n";
  const std::string error = load_error(text);
  EXPECT_CONTAINS(error, "plugin " + fs::canonical(text).string() + ": cannot load it:");
  EXPECT_CONTAINS(error, "expected an ELF shared library built against radarpr");
  fs::remove(text);
  EXPECT_CONTAINS(load_error(::testing::TempDir()), "is a directory");
}

TEST(PluginLoader, RefusesASharedLibraryWithoutTheEntryPoint) {
  const std::string error = load_error(NO_ENTRY_PLUGIN_PATH);
  EXPECT_CONTAINS(error, "no radarpr entry point");
  EXPECT_CONTAINS(error, "radarpr_plugin_abi");
  EXPECT_CONTAINS(error, "RADARPR_PLUGIN(register_function);");
}

TEST(PluginLoader, RefusesAPluginBuiltAgainstAnotherRadarprVersion) {
  const std::string error = load_error(VERSION_MISMATCH_PLUGIN_PATH);
  const RadarprPluginAbi& host = host_plugin_abi();
  EXPECT_CONTAINS(error, "incompatible build, rebuild it against this radarpr");
  // Both versions are printed.
  EXPECT_CONTAINS(error, fmt::format("radarpr version {}.99 differs from {}.{}", host.version_major,
                                     host.version_major, host.version_minor));
  EXPECT_CONTAINS(
      error, fmt::format("built against radarpr {}.99.{}", host.version_major, host.version_patch));
  EXPECT_CONTAINS(error, "this program is " + describe_plugin_abi(host));
  // Refused before its registration ran: its descriptor is unknown.
  EXPECT_FALSE(DescriptorRegistry::global().contains("plugin_future"));
}

TEST(PluginLoader, RefusesAPluginOfAnotherPluginAbi) {
  const std::string error = load_error(ABI_MISMATCH_PLUGIN_PATH);
  EXPECT_CONTAINS(error, fmt::format("plugin ABI 999 differs from {}", RADARPR_PLUGIN_ABI));
  EXPECT_FALSE(DescriptorRegistry::global().contains("plugin_other_abi"));
}

TEST(PluginLoader, RefusesADescriptorNameOfABuiltIn) {
  const std::string error = load_error(REFEREE_CLASH_PLUGIN_PATH);
  EXPECT_CONTAINS(error, "descriptor name 'referee' is already registered (built-in)");
  EXPECT_EQ(origin_of(DescriptorRegistry::global().info("referee")), "built-in");
}

TEST(PluginLoader, RefusesADescriptorNameAnotherPluginRegistered) {
  ASSERT_EQ(load_error(TWIN_A_PLUGIN_PATH), "");
  const std::string error = load_error(TWIN_B_PLUGIN_PATH);
  EXPECT_CONTAINS(error, "plugin " + fs::canonical(TWIN_B_PLUGIN_PATH).string());
  EXPECT_CONTAINS(error, "descriptor name 'plugin_twin' is already registered (plugin " +
                             fs::canonical(TWIN_A_PLUGIN_PATH).string() + ")");
  EXPECT_EQ(DescriptorRegistry::global().info("plugin_twin").plugin_path,
            fs::canonical(TWIN_A_PLUGIN_PATH).string());
}

TEST(PluginLoader, RefusesARegistrationThatThrowsSomethingNotAStdException) {
  // Without the catch-all, the plugin's own exception type escapes and ends the test program.
  const std::string error = load_error(THROWING_REGISTRATION_PLUGIN_PATH);
  EXPECT_CONTAINS(error, "plugin " + std::string(THROWING_REGISTRATION_PLUGIN_PATH) + ": ");
  EXPECT_CONTAINS(error, "its registration threw an exception that is not a std::exception");
}

TEST(PluginLoader, RefusesAPluginThatRegistersNoDescriptor) {
  const std::string error = load_error(REGISTERS_NOTHING_PLUGIN_PATH);
  EXPECT_CONTAINS(error, "plugin " + std::string(REGISTERS_NOTHING_PLUGIN_PATH) + ": ");
  EXPECT_CONTAINS(error, "it registers no descriptor");
}

TEST(PluginLoader, RefusesAnAbiRecordWithoutTheRegistrationFunction) {
  const std::string error = load_error(ABI_RECORD_ONLY_PLUGIN_PATH);
  EXPECT_CONTAINS(error, "no radarpr entry point: it exports no 'radarpr_plugin_register' symbol");
}

TEST(PluginLoader, NamesTheRadarprFunctionAPluginNeedsAndThisRadarprLacks) {
  const std::string error = load_error(MISSING_SYMBOL_PLUGIN_PATH);
  EXPECT_CONTAINS(error, "plugin " + std::string(MISSING_SYMBOL_PLUGIN_PATH) + ": ");
  // Demangled: the C++ name the author would recognise.
  EXPECT_CONTAINS(error,
                  "it needs symbol "
                  "radarpr::register_descriptors_of_a_newer_radarpr(radarpr::DescriptorRegistry&) "
                  "that this radarpr does not provide: built against another radarpr version?");
}

TEST(PluginLoader, ReportsTheVersionOfAPluginThatNeedsAMissingFunction) {
  // dlopen fails on the symbol first; the loader still reads the record and reports the version.
  const std::string error = load_error(MISSING_SYMBOL_OTHER_VERSION_PLUGIN_PATH);
  const RadarprPluginAbi& host = host_plugin_abi();
  EXPECT_CONTAINS(error, "incompatible build, rebuild it against this radarpr");
  EXPECT_CONTAINS(error, fmt::format("radarpr version {}.99 differs from {}.{}", host.version_major,
                                     host.version_major, host.version_minor));
}

TEST(PluginLoader, MessagesNameThePathAsGivenAndTheFileItLeadsTo) {
  const fs::path canonical = fs::canonical(VERSION_MISMATCH_PLUGIN_PATH);
  const fs::path given = canonical.parent_path() / "." / canonical.filename();
  const std::string error = load_error(given);
  EXPECT_CONTAINS(error, fmt::format("plugin {} ({}): ", given.string(), canonical.string()));
  EXPECT_CONTAINS(load_error("no/such/libplugin.so"),
                  "plugin no/such/libplugin.so: file not found");
}

TEST(PluginLoader, ReportsAPermissionErrorAsSuchNotAsAMissingFile) {
  if (::geteuid() == 0) GTEST_SKIP() << "running as root: every file is readable";
  const fs::path folder = fs::path(::testing::TempDir()) / "radarpr_locked_plugins";
  fs::remove_all(folder);
  fs::create_directories(folder);
  const fs::path unreadable = folder / "libunreadable.so";
  fs::copy_file(PROBE_PLUGIN_PATH, unreadable);
  fs::permissions(unreadable, fs::perms::none);
  EXPECT_CONTAINS(load_error(unreadable), "cannot read it: Permission denied");
  // A folder on the way that may not be entered.
  fs::permissions(unreadable, fs::perms::owner_all);
  fs::permissions(folder, fs::perms::none);
  const std::string error = load_error(unreadable);
  EXPECT_CONTAINS(error, "cannot access it: Permission denied");
  EXPECT_EQ(error.find("file not found"), std::string::npos) << error;
  fs::permissions(folder, fs::perms::owner_all);
  fs::remove_all(folder);
}

TEST(DescriptorRegistry, AnUnknownDescriptorHintsAtPlugins) {
  try {
    DescriptorRegistry::global().info("not_loaded_yet");
    ADD_FAILURE() << "an unknown name was found";
  } catch (const std::invalid_argument& error) {
    EXPECT_CONTAINS(error.what(), "unknown descriptor 'not_loaded_yet' (known: ");
    EXPECT_CONTAINS(error.what(), "--plugin PATH, \"plugins\" in the config");
  }
}

// The compatibility rule on hand-made records: each field that differs is named.
TEST(PluginCompatibility, NamesWhatDiffers) {
  const RadarprPluginAbi host = host_plugin_abi();
  EXPECT_FALSE(plugin_incompatibility(host, host));
  RadarprPluginAbi patch = host;
  patch.version_patch = host.version_patch + 7;  // a patch release is compatible
  EXPECT_FALSE(plugin_incompatibility(patch, host));
  RadarprPluginAbi major = host;
  major.version_major = host.version_major + 1;
  EXPECT_CONTAINS(*plugin_incompatibility(major, host), "major.minor must match");
  RadarprPluginAbi layout = host;
  layout.record_size = 12;
  EXPECT_CONTAINS(*plugin_incompatibility(layout, host), "ABI record is of another layout");
  RadarprPluginAbi library = host;
  library.standard_library_abi = host.standard_library_abi == 0 ? 1 : 0;
  EXPECT_CONTAINS(*plugin_incompatibility(library, host), "ABI flag");
  RadarprPluginAbi sizes = host;
  sizes.sizeof_string = 8;
  EXPECT_CONTAINS(
      *plugin_incompatibility(sizes, host),
      fmt::format("sizeof(std::string) is 8 in the plugin, {} here", host.sizeof_string));
}

TEST(PluginLoader, SplitsAColonSeparatedList) {
  EXPECT_EQ(split_plugin_list("a.so::/b/c.so:"), (std::vector<fs::path>{"a.so", "/b/c.so"}));
  EXPECT_TRUE(split_plugin_list("").empty());
}

}  // namespace
}  // namespace radarpr
