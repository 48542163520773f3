#pragma once
// Calculator: Inventor's expression engine (docs/SCENE-FORMAT.md section 1.10).

#include <memory>
#include <string>
#include <vector>

#include <volsg/engines/Engine.h>

namespace volsg {

/// Evaluates `expression` (one or more statements per string, separated by ';') once per
/// value index i, over as many indices as the longest input the expressions use:
///
/// - inputs a..h (MFFloat) and A..H (MFVec3f); outputs oa..od (MFFloat) and oA..oD (MFVec3f);
///   temporaries ta..th and tA..tH (0 at the start of each index);
/// - `oa = ...;` assigns a float, `oA = ...;` a vector, `oA[1] = ...;` one component;
/// - operators `? :`, `||`, `&&`, `==` `!=`, `<` `>` `<=` `>=`, `+` `-`, `*` `/` `%`, unary
///   `-` and `!`, parentheses, `A[0]` (a component); a vector times or over a float;
/// - functions cos sin tan acos asin atan atan2 cosh sinh tanh sqrt pow exp log log10 ceil
///   floor fabs fmod rand (a number in [0, 1], repeatable: the same sequence each run),
///   length dot cross normalize vec3f;
/// - constants MAXFLOAT MINFLOAT M_E M_LOG2E M_LOG10E M_LN2 M_LN10 M_PI M_PI_2 M_PI_4 M_1_PI
///   M_2_PI M_2_SQRTPI M_SQRT2 M_SQRT1_2, and numbers (`1`, `.5`, `2e-3`).
///
/// An output no statement assigns keeps its value. A malformed expression is an Error naming
/// it, thrown when the expression is parsed (on reading it from a file, or on evaluation).
class Calculator : public Inherit<Engine, Calculator> {
public:
    static constexpr const char* typeName = "Calculator";
    static constexpr bool inventorBuiltin() { return true; }
    MFFloat a{this, "a", {0.0f}}, b{this, "b", {0.0f}}, c{this, "c", {0.0f}}, d{this, "d", {0.0f}},
        e{this, "e", {0.0f}}, f{this, "f", {0.0f}}, g{this, "g", {0.0f}}, h{this, "h", {0.0f}};
    MFVec3f A{this, "A", {glm::vec3(0.0f)}}, B{this, "B", {glm::vec3(0.0f)}},
        C{this, "C", {glm::vec3(0.0f)}}, D{this, "D", {glm::vec3(0.0f)}},
        E{this, "E", {glm::vec3(0.0f)}}, F{this, "F", {glm::vec3(0.0f)}},
        G{this, "G", {glm::vec3(0.0f)}}, H{this, "H", {glm::vec3(0.0f)}};
    MFString expression{this, "expression"};

    void evaluate(const EngineContext& context) override;
    void readDone(const ReadContext& context) override; ///< parses, so errors show on reading

    /// Parses an expression; throws volsg::Error with the position of the fault.
    static void check(const std::string& expression);

    struct Program;

protected:
    Calculator();
    ~Calculator() override;
    std::vector<OutputSpec> outputSpecs() const override;

private:
    friend class Inherit<Engine, Calculator>;
    void compile();
    std::vector<std::string> compiledFrom_;
    std::unique_ptr<Program> program_;
    std::uint64_t random_ = 0x853c49e6748fea9bULL;
};

} // namespace volsg
