#pragma once
// Engines: objects with input fields and outputs that compute the outputs from the inputs (and
// the time); field connections carry their outputs into node fields (docs/SCENE-FORMAT.md
// section 1.10).

#include <cstddef>
#include <memory>
#include <string_view>
#include <utility>
#include <vector>

#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

/// What an engine sees when it is evaluated.
struct EngineContext {
    double seconds = 0.0; ///< the scene time (the global field realTime)
};

/// Base of the engine types (ElapsedTime, Calculator, ...). Like Inventor's SoEngine it is a
/// field container that is never a child of a group: it exists as the source of field
/// connections (`translation = Calculator { ... } . oA`), which keep it alive. It derives from
/// Node for its fields, name, version and DEF/USE in files; the reader refuses an engine where
/// a node is expected.
///
/// Inputs are ordinary fields; outputs are fields without owner, made on first use, that only
/// evaluate() sets (and only when the value changes, so what reads them sees a new version
/// only then).
class Engine : public Inherit<Node, Engine> {
public:
    static constexpr const char* typeName = "Engine";
    static constexpr bool inventorBuiltin() { return true; }

    std::size_t outputCount() const;
    Field* outputAt(std::size_t i);
    Field* output(std::string_view name);

    /// Computes the outputs from the inputs. Called by the evaluator (Evaluator.h) after the
    /// inputs' connections have been brought up to date.
    virtual void evaluate(const EngineContext& context) = 0;

protected:
    ~Engine() override;
    struct OutputSpec {
        const char* name;
        const char* type; ///< a field type name (SFFloat, MFVec3f, ...)
    };
    /// The outputs of this engine, in order.
    virtual std::vector<OutputSpec> outputSpecs() const = 0;
    /// Drops the outputs so they are made again from outputSpecs() (an engine whose output type
    /// follows an input's type).
    void resetOutputs() { outputs_.clear(); }
    /// The i-th output as its field class (which outputSpecs() decides).
    template <class F> F& out(std::size_t i) { return static_cast<F&>(*outputAt(i)); }
    /// Sets an output to `value` when it differs (or was never set).
    template <class F, class V> void set(std::size_t i, const V& value) {
        F& f = out<F>(i);
        if (f.isDefault() || !(f.getValue() == value)) f.setValue(value);
    }
    template <class F, class V> void setValues(std::size_t i, std::vector<V> values) {
        F& f = out<F>(i);
        if (f.isDefault() || f.getValues() != values) f.setValues(std::move(values));
    }

private:
    void makeOutputs();
    std::vector<std::unique_ptr<Field>> outputs_;
};

/// The field of a connection source: a field of a node, or an output of an engine (an engine
/// input of that name comes first, as in Inventor). Null if it has none of that name.
Field* connectionSourceField(Node& source, std::string_view name);

} // namespace volsg
