#include <volsg/fields/Fields.h>
#include <volsg/io/GraphCompare.h>
#include <volsg/io/UnknownNode.h>

#include <sstream>
#include <unordered_map>

namespace volsg {

namespace {

// Writes a field's value for a message; node values are only named.
class ValueText final : public FieldOutput {
public:
    std::ostream& stream() override { return out_; }
    void writeNode(const Node* node) override {
        out_ << (node ? std::string(node->type().name()) + " {...}" : std::string("NULL"));
    }
    void newline() override { out_ << ' '; }
    static std::string of(const Field& field) {
        ValueText text;
        try {
            field.write(text);
        } catch (const std::exception& e) {
            return std::string("<") + e.what() + ">";
        }
        std::string s = std::move(text.out_).str();
        if (s.size() > 200) s = s.substr(0, 200) + "...";
        return s;
    }

private:
    std::ostringstream out_;
};

std::string typeNameOf(const Node& node) {
    if (const auto* unknown = dynamic_cast<const UnknownNode*>(&node))
        return unknown->fileTypeName() + " (unknown)";
    return node.type().name();
}

class GraphComparer {
public:
    GraphComparer(std::string* why, double tolerance) : why_(why), tolerance_(tolerance) {}

    bool compare(const Node* a, const Node* b, const std::string& where) {
        if (!a || !b)
            return a == b || fail(where, a ? "NULL on the right only" : "NULL on the left only");
        const auto ia = aToB_.find(a);
        const auto ib = bToA_.find(b);
        if (ia != aToB_.end() || ib != bToA_.end()) {
            if (ia == aToB_.end() || ib == bToA_.end() || ia->second != b || ib->second != a)
                return fail(where, "sharing differs (a node reached twice on one side is not "
                                   "the same node on the other)");
            return true; // compared where it was first reached
        }
        aToB_.emplace(a, b);
        bToA_.emplace(b, a);

        const std::string here = where + "/" + typeNameOf(*a);
        if (&a->type() != &b->type() || typeNameOf(*a) != typeNameOf(*b))
            return fail(here, "type " + typeNameOf(*a) + " vs " + typeNameOf(*b));
        if (a->getName() != b->getName())
            return fail(here, "name '" + a->getName() + "' vs '" + b->getName() + "'");
        if (a->fieldCount() != b->fieldCount())
            return fail(here, std::to_string(a->fieldCount()) + " fields vs " +
                                  std::to_string(b->fieldCount()));
        for (std::size_t i = 0, n = a->fieldCount(); i < n; ++i)
            if (!compareFields(a->fieldAt(i), b->fieldAt(i), here)) return false;

        const auto* ca = a->children();
        const auto* cb = b->children();
        if (!ca || !cb)
            return (ca == nullptr) == (cb == nullptr) || fail(here, "group vs non-group");
        if (ca->size() != cb->size())
            return fail(here,
                        std::to_string(ca->size()) + " children vs " + std::to_string(cb->size()));
        for (std::size_t i = 0; i < ca->size(); ++i)
            if (!compare((*ca)[i].get(), (*cb)[i].get(), here + "[" + std::to_string(i) + "]"))
                return false;
        return true;
    }

private:
    bool compareFields(const Field* fa, const Field* fb, const std::string& here) {
        if (!fa || !fb) return fa == fb || fail(here, "a missing field");
        const std::string where = here + "." + fa->name();
        if (std::string_view(fa->name()) != fb->name())
            return fail(here, std::string("field '") + fa->name() + "' vs '" + fb->name() + "'");
        if (std::string_view(fa->typeName()) != fb->typeName())
            return fail(where, std::string("type ") + fa->typeName() + " vs " + fb->typeName());
        if (fa->isDefault() != fb->isDefault())
            return fail(where,
                        fa->isDefault() ? "default on the left only" : "default on the right only");
        if (fa->isIgnored() != fb->isIgnored())
            return fail(where,
                        fa->isIgnored() ? "ignored on the left only" : "ignored on the right only");
        const FieldConnection* ca = fa->connection();
        const FieldConnection* cb = fb->connection();
        if ((ca == nullptr) != (cb == nullptr))
            return fail(where, ca ? "connected on the left only" : "connected on the right only");
        if (ca) {
            if (ca->sourceField != cb->sourceField)
                return fail(where, "connected from '" + ca->sourceField + "' vs '" +
                                       cb->sourceField + "'");
            if (!compare(ca->source.get(), cb->source.get(), where + " = ")) return false;
        }
        if (const auto* sa = dynamic_cast<const SFNode*>(fa)) {
            const auto* sb = dynamic_cast<const SFNode*>(fb);
            return sb ? compare(sa->getValue(), sb->getValue(), where)
                      : fail(where, "not an SFNode");
        }
        if (const auto* ma = dynamic_cast<const MFNode*>(fa)) {
            const auto* mb = dynamic_cast<const MFNode*>(fb);
            if (!mb) return fail(where, "not an MFNode");
            if (ma->getValues().size() != mb->getValues().size())
                return fail(where, std::to_string(ma->getValues().size()) + " nodes vs " +
                                       std::to_string(mb->getValues().size()));
            for (std::size_t i = 0; i < ma->getValues().size(); ++i)
                if (!compare(ma->getValues()[i].get(), mb->getValues()[i].get(),
                             where + "[" + std::to_string(i) + "]"))
                    return false;
            return true;
        }
        // A field that is default on both sides is not written; its value does not count (a
        // binary file may carry a value and flag it default).
        if (fa->isDefault()) return true;
        if (!fa->equals(*fb) && !(tolerance_ > 0.0 && valuesClose(*fa, *fb, tolerance_)))
            return fail(where, "value " + ValueText::of(*fa) + " vs " + ValueText::of(*fb));
        return true;
    }

    bool fail(const std::string& where, const std::string& what) {
        if (why_) *why_ = where + ": " + what;
        return false;
    }

    std::string* why_;
    double tolerance_;
    std::unordered_map<const Node*, const Node*> aToB_, bToA_;
};

} // namespace

bool graphsEqual(const Node& a, const Node& b, std::string* why, double relativeTolerance) {
    GraphComparer comparer(why, relativeTolerance);
    return comparer.compare(&a, &b, "");
}

} // namespace volsg
