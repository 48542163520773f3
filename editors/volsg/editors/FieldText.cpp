#include <volsg/editors/FieldText.h>

#include <cstring>
#include <memory>
#include <sstream>

#include <volsg/core/Error.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/Tokenizer.h>

namespace volsg {

namespace {

class TextOutput final : public FieldOutput {
public:
    std::ostream& stream() override { return out; }
    void writeNode(const Node*) override { throw Error("node values are not text"); }
    void newline() override { out << ' '; }
    std::ostringstream out;
};

class TextInput final : public FieldInput {
public:
    TextInput(std::string_view text, const std::string& name) : tokens_(text, name) {}
    Tokenizer& tokens() override { return tokens_; }
    ref_ptr<Node> readNode() override { tokens_.fail("a node value cannot be typed as text"); }

private:
    Tokenizer tokens_;
};

} // namespace

bool isTextField(const Field& field) {
    return std::strcmp(field.typeName(), "SFNode") != 0 &&
           std::strcmp(field.typeName(), "MFNode") != 0;
}

std::string fieldValueText(const Field& field) {
    if (!isTextField(field))
        throw Error(std::string("field '") + field.name() + "' holds nodes, which are not text");
    TextOutput out;
    field.write(out);
    return out.out.str();
}

void setFieldFromText(Field& field, std::string_view text) {
    if (!isTextField(field))
        throw Error(std::string("field '") + field.name() + "' holds nodes, which are not text");
    // Read into a scratch field of the same type first, so a bad value changes nothing.
    std::unique_ptr<Field> scratch;
    if (std::strcmp(field.typeName(), "SFEnum") == 0 ||
        std::strcmp(field.typeName(), "SFBitMask") == 0) {
        // Enum names live with the field: read into the field itself, restoring on error.
        const std::string before = fieldValueText(field);
        const bool wasDefault = field.isDefault();
        try {
            TextInput in(text, std::string("field ") + field.name());
            field.read(in);
            if (!in.tokens().atEnd()) in.tokens().fail("more than one value");
        } catch (...) {
            TextInput restore(before, "restore");
            field.read(restore);
            field.setDefault(wasDefault);
            throw;
        }
        return;
    }
    scratch = createFieldOfType(field.typeName(), nullptr, field.name());
    if (!scratch) throw Error(std::string("field type ") + field.typeName() + " is not editable");
    TextInput in(text, std::string("field ") + field.name());
    scratch->read(in);
    if (!in.tokens().atEnd()) in.tokens().fail("more than one value");
    field.copyFrom(*scratch);
}

} // namespace volsg
