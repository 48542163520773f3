#pragma once
// Small command-line helpers shared by the volsg tools: every parse error is a volsg::Error
// the tool prints as one line.

#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

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

glm::ivec2 parseSize(const std::string& text); ///< "WxH"
glm::vec3 parseColor(const std::string& text); ///< "R,G,B" in [0,1]
/// A number in (0, 1] for `option` (the stereo eye separation as a fraction of focalDistance).
double parseFraction(const std::string& text, std::string_view option);
std::string extensionOf(const std::string& path); ///< lower case, with the dot

} // namespace volsg::cli
