#pragma once
// GlobalField: a named field of the whole scene, as a connection source (Inventor's
// SoGlobalField; `realTime` is the scene time).

#include <string>

#include <volsg/engines/Engine.h>

namespace volsg {

/// Written `GlobalField { type SFTime realTime 0 }`: one field whose name and type the file
/// gives. A field connected to it takes its value (`timeIn = GlobalField { ... } . realTime`).
/// The evaluator sets every global field named `realTime` to the scene time
/// (EngineContext::seconds) before it evaluates anything else.
class GlobalField : public Inherit<Engine, GlobalField> {
public:
    static constexpr const char* typeName = "GlobalField";
    static constexpr bool inventorBuiltin() { return true; }

    SFName type{this, "type"};

    /// The field holding the value, or null before makeValueField().
    Field* valueField() const { return value_.get(); }
    /// Makes the value field `name`, of the field type `type` names. Null when `type` is not
    /// a field type or the value field exists already.
    Field* makeValueField(const std::string& name);

    std::size_t fieldCount() const override;
    Field* fieldAt(std::size_t i) override;
    using Node::fieldAt;

    void evaluate(const EngineContext& context) override;

protected:
    ~GlobalField() override;
    std::vector<OutputSpec> outputSpecs() const override { return {}; }

private:
    std::string valueName_;
    std::unique_ptr<Field> value_;
};

} // namespace volsg
