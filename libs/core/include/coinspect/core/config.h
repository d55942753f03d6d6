// INI configuration with strict reading: every value is checked, every key must be known.
//
// Read through MRPT's CConfigFileMemory (never CConfigFile, which writes files back). A
// component reads its keys with the typed getters; when all components are done, the owner calls
// requireAllKeysUsed(), so that a misspelt key is an error instead of a silent default.
#pragma once

#include <Eigen/Core>

#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace coinspect {

class Config {
 public:
  // Throws InputError when the file cannot be read.
  static Config fromFile(const std::filesystem::path& path);
  // `source` names the text in error messages (a file name, "--set", "<generated>"); relative
  // paths in values are taken from `folder` (the current directory when empty).
  static Config fromText(const std::string& text, const std::string& source,
                         const std::filesystem::path& folder = {});

  Config(Config&&) noexcept;
  Config& operator=(Config&&) noexcept;
  Config(const Config&) = delete;
  Config& operator=(const Config&) = delete;
  ~Config();

  const std::string& source() const { return source_; }
  // Folder of the file it was read from (for relative paths in values); for text, fromText's.
  const std::filesystem::path& folder() const { return folder_; }

  std::vector<std::string> sections() const;
  std::vector<std::string> keys(const std::string& section) const;
  bool hasSection(const std::string& section) const;
  bool has(const std::string& section, const std::string& key) const;

  // Required values: a missing key or a malformed value throws InputError naming the source,
  // "[section] key" and the offending text.
  std::string getString(const std::string& section, const std::string& key) const;
  double getDouble(const std::string& section, const std::string& key) const;
  long long getInt(const std::string& section, const std::string& key) const;
  bool getBool(const std::string& section, const std::string& key) const;
  std::vector<double> getDoubles(const std::string& section, const std::string& key) const;
  Eigen::Vector3d getVector3(const std::string& section, const std::string& key) const;

  // Optional values: the fallback only when the key is absent; a present malformed value throws.
  std::string getString(const std::string& section, const std::string& key,
                        const std::string& fallback) const;
  double getDouble(const std::string& section, const std::string& key, double fallback) const;
  long long getInt(const std::string& section, const std::string& key, long long fallback) const;
  bool getBool(const std::string& section, const std::string& key, bool fallback) const;
  Eigen::Vector3d getVector3(const std::string& section, const std::string& key,
                             const Eigen::Vector3d& fallback) const;

  // A path value, resolved against folder() when relative.
  std::filesystem::path getPath(const std::string& section, const std::string& key) const;

  // Marks a key as used without reading it (for keys handled by a later stage).
  void markUsed(const std::string& section, const std::string& key) const;

  void set(const std::string& section, const std::string& key, const std::string& value);
  // Applies "section.key=value" (as given to --set); malformed text throws InputError.
  void applyOverride(const std::string& assignment);

  // Throws InputError naming every key of `sectionsToCheck` (all sections when empty) that no
  // getter has read.
  void requireAllKeysUsed(const std::vector<std::string>& sectionsToCheck = {}) const;

  // The whole content as INI text (for run headers and exports).
  std::string toText() const;

 private:
  Config();
  std::optional<std::string> raw(const std::string& section, const std::string& key) const;
  std::string required(const std::string& section, const std::string& key) const;
  [[noreturn]] void fail(const std::string& section, const std::string& key,
                         const std::string& what) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string source_;
  std::filesystem::path folder_;
  mutable std::set<std::pair<std::string, std::string>> used_;
};

}  // namespace coinspect
