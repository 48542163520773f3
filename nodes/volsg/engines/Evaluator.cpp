#include <volsg/core/Error.h>
#include <volsg/engines/AnimatedNodes.h>
#include <volsg/engines/Engine.h>
#include <volsg/engines/Evaluator.h>
#include <volsg/engines/GlobalField.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/UnknownNode.h>

#include <iostream>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace volsg {

namespace {

std::string describe(const Node& node) {
    std::string type = node.type().name();
    if (const auto* u = dynamic_cast<const UnknownNode*>(&node)) type = u->fileTypeName();
    return node.getName().empty() ? type : type + " '" + node.getName() + "'";
}

/// Every node and engine reachable from the root, without recursion (a file may chain
/// millions of connections).
std::vector<Node*> reachable(Node& root) {
    std::vector<Node*> out, stack{&root};
    std::unordered_set<const Node*> seen{&root};
    auto push = [&](Node* n) {
        if (n && seen.insert(n).second) stack.push_back(n);
    };
    while (!stack.empty()) {
        Node* node = stack.back();
        stack.pop_back();
        out.push_back(node);
        for (std::size_t i = 0, n = node->fieldCount(); i < n; ++i) {
            Field* f = node->fieldAt(i);
            if (!f) continue;
            if (const FieldConnection* c = f->connection()) push(c->source.get());
            if (const auto* sf = dynamic_cast<const SFNode*>(f)) push(sf->getValue());
            if (const auto* mf = dynamic_cast<const MFNode*>(f))
                for (const auto& v : mf->getValues())
                    push(v.get());
        }
        if (auto* children = node->children())
            for (const auto& child : *children)
                push(child.get());
    }
    return out;
}

} // namespace

ConnectionEvaluator::ConnectionEvaluator(WarningSink sink) : sink_(std::move(sink)) {}

void ConnectionEvaluator::warn(const Node& node, const std::string& message) {
    // Where the node came from, as a read error names it ("scene.iv:12:3: ..."), bounded and
    // printable like every message.
    const SourcePlace& place = node.sourcePlace();
    const std::string line =
        Error(message, place.file ? *place.file : std::string(), place.line, place.column).what();
    if (!warned_.insert(line).second) return;
    if (sink_)
        sink_(line);
    else
        std::cerr << "volsg: " << line << '\n';
}

std::size_t ConnectionEvaluator::evaluate(Node& root, double seconds) {
    const std::vector<Node*> nodes = reachable(root);

    // Dependency order by an iterative depth-first search over the connection sources:
    // a node is placed after every source of its fields' connections.
    enum class Mark : unsigned char { None, Open, Done };
    std::unordered_map<const Node*, Mark> mark;
    std::unordered_set<const Field*> broken;
    std::vector<Node*> order;
    order.reserve(nodes.size());
    struct Frame {
        Node* node;
        std::size_t field;
    };
    for (Node* start : nodes) {
        if (mark[start] != Mark::None) continue;
        std::vector<Frame> stack{{start, 0}};
        mark[start] = Mark::Open;
        while (!stack.empty()) {
            Frame& top = stack.back();
            Node* node = top.node;
            bool descended = false;
            while (top.field < node->fieldCount()) {
                Field* f = node->fieldAt(top.field++);
                const FieldConnection* c = f ? f->connection() : nullptr;
                if (!c || !c->source) continue;
                Node* source = c->source.get();
                const Mark m = mark[source];
                if (m == Mark::Open) {
                    broken.insert(f);
                    warn(*node, "connection cycle: field '" + std::string(f->name()) + "' of " +
                                    describe(*node) + " from '" + c->sourceField + "' of " +
                                    describe(*source) + " is not evaluated");
                } else if (m == Mark::None) {
                    mark[source] = Mark::Open;
                    stack.push_back({source, 0});
                    descended = true;
                    break;
                }
            }
            if (descended) continue;
            mark[node] = Mark::Done;
            order.push_back(node);
            stack.pop_back();
        }
    }

    EngineContext context;
    context.seconds = seconds;
    std::size_t changed = 0;
    for (Node* node : order) {
        if (auto* global = dynamic_cast<GlobalField*>(node)) global->evaluate(context);
        for (std::size_t i = 0, n = node->fieldCount(); i < n; ++i) {
            Field* f = node->fieldAt(i);
            FieldConnection* c = f ? f->connection() : nullptr;
            if (!c || !c->source || broken.count(f)) continue;
            Field* from = connectionSourceField(*c->source, c->sourceField);
            if (!from) {
                warn(*node, "field '" + std::string(f->name()) + "' of " + describe(*node) +
                                " is connected to '" + c->sourceField + "', which " +
                                describe(*c->source) + " does not have");
                continue;
            }
            if (c->lastCopied && c->lastCopied->equals(*from) &&
                c->lastCopied->isDefault() == from->isDefault())
                continue; // the source has not changed since it was copied
            try {
                if (assignConverted(*f, *from)) ++changed;
                c->lastCopied = cloneField(*from);
            } catch (const Error& e) {
                warn(*node, "field '" + std::string(f->name()) + "' of " + describe(*node) + ": " +
                                e.message());
            }
        }
        if (auto* engine = dynamic_cast<Engine*>(node)) {
            if (!dynamic_cast<GlobalField*>(node)) {
                try {
                    engine->evaluate(context);
                } catch (const Error& e) {
                    warn(*node, describe(*node) + ": " + e.message());
                }
            }
        } else if (auto* animated = dynamic_cast<Animated*>(node)) {
            const std::uint64_t before = node->version();
            animated->animate(seconds);
            if (node->version() != before) ++changed;
        }
    }
    return changed;
}

std::size_t evaluateConnections(Node& root, double seconds) {
    ConnectionEvaluator evaluator;
    return evaluator.evaluate(root, seconds);
}

} // namespace volsg
