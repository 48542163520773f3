#pragma once
// Small command-line helpers shared by the volsg tools: every parse error is a volsg::Error
// the tool prints as one line.

#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/volumescene/SceneForFile.h>

namespace volsg::cli {

/// The arguments after the program name, consumed front to back.
class Arguments {
public:
    Arguments(int argc, char** argv);
    bool empty() const { return next_ >= args_.size(); }
    std::string_view peek() const { return args_[next_]; }
    std::string take();
    std::string value(std::string_view option); ///< the word after `option`, or an error
    int intValue(std::string_view option, int min, int max);

private:
    std::vector<std::string> args_;
    std::size_t next_ = 0;
};

/// A tool's main(): `body` with the arguments; an exception it throws (a volsg::Error for bad
/// input) is printed as one line "name: message" on stderr and gives exit status 1.
int runTool(const char* name, int argc, char** argv, const std::function<int(Arguments&)>& body);

/// The options a tool knows, each with what it does, and the loop that reads a command line.
class Options {
public:
    /// What an option does; it takes its values from `args` (`option`: the name as given).
    using Action = std::function<void(Arguments& args, const std::string& option)>;
    /// What a tool does with a word that names no option.
    using Operand = std::function<void(const std::string& word)>;

    /// The spellings of one option: "--output" or {"-o", "--output"}.
    struct Names {
        Names(const char* name) : list{name} {}
        Names(std::initializer_list<const char*> names) : list(names.begin(), names.end()) {}
        std::vector<std::string> list;
    };

    /// `name`, with whatever values `action` takes: `action`.
    Options& add(const Names& names, Action action);
    /// `name`: sets `target` to `value`.
    Options& flag(const Names& names, bool& target, bool value = true);
    /// `name VALUE`: `set(VALUE)`.
    Options& value(const Names& names, std::function<void(const std::string&)> set);
    /// `name VALUE`: VALUE into `target`.
    Options& text(const Names& names, std::string& target);
    /// `name N`: a whole number in [min, max] into `target`; `*given` becomes true.
    Options& integer(const Names& names, int& target, int min, int max, bool* given = nullptr);
    /// `name WxH` (parseSize); `*given` becomes true.
    Options& size(const Names& names, int& width, int& height, bool* given = nullptr);
    /// `name R,G,B` (parseColor).
    Options& color(const Names& names, glm::vec3& target);
    /// `name F`, a number in (0, 1] (parseFraction).
    Options& fraction(const Names& names, double& target);
    /// The layout of a raw volume given as the scene: `--dims X Y Z`, `--type
    /// uchar|ushort|short|float` (also UBYTE, USHORT, SHORT, FLOAT, uint8, uint16, int16,
    /// float32), `--spacing SX SY SZ`, `--big-endian`, `--header-skip N`. Any of them makes
    /// `open.raw` set; --dims is then required (checkRawLayout).
    Options& rawVolume(OpenFileOptions& open);

    /// Reads the command line front to back: -h or --help prints `usage` on stdout and returns
    /// false (the tool exits with 0); an option does its action; any other word goes to
    /// `operand`, except that one starting with '-' is an unknown option. Without an operand
    /// every word outside the table is an unknown argument. True when all was read.
    bool read(Arguments& args, const char* usage, const Operand& operand) const;

private:
    std::vector<std::pair<std::string, Action>> actions_;
};

/// The operand of a tool that reads one scene file: into `scene`; a second one is an error.
Options::Operand sceneOperand(std::string& scene);

/// Prints `usage` on stderr for a command line that lacks what the tool needs: exit status 2.
int usageError(const char* usage);

glm::ivec2 parseSize(const std::string& text); ///< "WxH"
glm::vec3 parseColor(const std::string& text); ///< "R,G,B" in [0,1]
/// A number in (0, 1] for `option` (the stereo eye separation as a fraction of focalDistance).
double parseFraction(const std::string& text, std::string_view option);
std::string extensionOf(const std::string& path); ///< lower case, with the dot

/// A tool's usage text whose "%s" is replaced by the options text of rawVolume().
std::string withRawUsage(const char* usage);
/// After reading the command line: a raw layout without --dims is an error.
void checkRawLayout(const OpenFileOptions& open);

} // namespace volsg::cli
