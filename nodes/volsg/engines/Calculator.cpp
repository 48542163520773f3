#include <volsg/core/Error.h>
#include <volsg/engines/Calculator.h>

#include <algorithm>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <numbers>

namespace volsg {

namespace {

enum class Kind { Float, Vec };

/// A register: input a..h / A..H, output oa..od / oA..oD, temporary ta..th / tA..tH.
struct Reg {
    enum class Bank { In, Out, Tmp } bank;
    Kind kind;
    int index; // 0..7 (outputs 0..3)
};

struct Value {
    double f = 0.0;
    glm::dvec3 v{0.0};
};

} // namespace

/// A parsed expression: a tree of nodes, each with its result kind.
struct Calculator::Program {
    struct Expr {
        enum class Op {
            Number,
            Reg,
            Component,
            Neg,
            Not,
            Add,
            Sub,
            Mul,
            Div,
            Mod,
            Eq,
            Ne,
            Lt,
            Gt,
            Le,
            Ge,
            And,
            Or,
            Cond,
            Func1,
            Atan2,
            Pow,
            Fmod,
            Length,
            Dot,
            Cross,
            Normalize,
            Vec3f
        } op;
        Kind kind = Kind::Float;
        double number = 0.0;
        Reg reg{};
        int component = 0;
        double (*func)(double) = nullptr;
        bool isRand = false;
        std::vector<std::unique_ptr<Expr>> args;
    };
    struct Statement {
        Reg target;
        int component = -1; // oA[1] = ...
        std::unique_ptr<Expr> value;
    };
    std::vector<Statement> statements;
    bool inUsed[16] = {};
    bool outUsed[8] = {};
};

namespace {

using Expr = Calculator::Program::Expr;
using Op = Expr::Op;

struct Tok {
    enum class T { End, Number, Name, Sym } t = T::End;
    std::string text;
    double number = 0.0;
    std::size_t pos = 0;
};

class Parser {
public:
    Parser(const std::string& text, Calculator::Program& program) : text_(text), program_(program) {
        advance();
    }

    void parseAll() {
        while (tok_.t != Tok::T::End) {
            if (isSym(";")) {
                advance();
                continue;
            }
            parseStatement();
            if (tok_.t != Tok::T::End && !isSym(";"))
                fail("expected ';' or the end of the expression");
        }
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw Error("Calculator expression \"" + text_ + "\", at character " +
                    std::to_string(tok_.pos + 1) + ": " + what +
                    (tok_.t == Tok::T::End ? ", found the end" : ", found '" + tok_.text + "'"));
    }

    bool isSym(const char* s) const { return tok_.t == Tok::T::Sym && tok_.text == s; }

    void advance() {
        std::size_t i = pos_;
        while (i < text_.size() &&
               (text_[i] == ' ' || text_[i] == '\t' || text_[i] == '\n' || text_[i] == '\r'))
            ++i;
        tok_ = Tok{};
        tok_.pos = i;
        if (i >= text_.size()) {
            pos_ = i;
            return;
        }
        const char c = text_[i];
        if ((c >= '0' && c <= '9') ||
            (c == '.' && i + 1 < text_.size() && text_[i + 1] >= '0' && text_[i + 1] <= '9')) {
            std::size_t j = i;
            while (j < text_.size() && ((text_[j] >= '0' && text_[j] <= '9') || text_[j] == '.'))
                ++j;
            if (j < text_.size() && (text_[j] == 'e' || text_[j] == 'E')) {
                std::size_t k = j + 1;
                if (k < text_.size() && (text_[k] == '+' || text_[k] == '-')) ++k;
                if (k < text_.size() && text_[k] >= '0' && text_[k] <= '9') {
                    j = k;
                    while (j < text_.size() && text_[j] >= '0' && text_[j] <= '9')
                        ++j;
                }
            }
            tok_.t = Tok::T::Number;
            tok_.text = text_.substr(i, j - i);
            const auto [p, ec] =
                std::from_chars(tok_.text.data(), tok_.text.data() + tok_.text.size(), tok_.number);
            if (ec != std::errc() || p != tok_.text.data() + tok_.text.size() ||
                !std::isfinite(tok_.number))
                fail("malformed number");
            pos_ = j;
            return;
        }
        if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_') {
            std::size_t j = i;
            while (j < text_.size() &&
                   ((text_[j] >= 'a' && text_[j] <= 'z') || (text_[j] >= 'A' && text_[j] <= 'Z') ||
                    (text_[j] >= '0' && text_[j] <= '9') || text_[j] == '_'))
                ++j;
            tok_.t = Tok::T::Name;
            tok_.text = text_.substr(i, j - i);
            pos_ = j;
            return;
        }
        static const char* twoChar[] = {"<=", ">=", "==", "!=", "&&", "||"};
        for (const char* s : twoChar)
            if (text_.compare(i, 2, s) == 0) {
                tok_.t = Tok::T::Sym;
                tok_.text = s;
                pos_ = i + 2;
                return;
            }
        if (std::string("+-*/%<>!?:()[],;=").find(c) == std::string::npos) {
            tok_.text = std::string(1, c);
            fail("unexpected character");
        }
        tok_.t = Tok::T::Sym;
        tok_.text = std::string(1, c);
        pos_ = i + 1;
    }

    void expect(const char* s) {
        if (!isSym(s)) fail(std::string("expected '") + s + "'");
        advance();
    }

    static bool regOf(const std::string& name, Reg& reg) {
        auto lowerIn = [](char c, char last) { return c >= 'a' && c <= last; };
        auto upperIn = [](char c, char last) { return c >= 'A' && c <= last; };
        if (name.size() == 1) {
            if (lowerIn(name[0], 'h'))
                reg = {Reg::Bank::In, Kind::Float, name[0] - 'a'};
            else if (upperIn(name[0], 'H'))
                reg = {Reg::Bank::In, Kind::Vec, name[0] - 'A'};
            else
                return false;
            return true;
        }
        if (name.size() != 2) return false;
        const char bank = name[0], r = name[1];
        if (bank == 't' && lowerIn(r, 'h'))
            reg = {Reg::Bank::Tmp, Kind::Float, r - 'a'};
        else if (bank == 't' && upperIn(r, 'H'))
            reg = {Reg::Bank::Tmp, Kind::Vec, r - 'A'};
        else if (bank == 'o' && lowerIn(r, 'd'))
            reg = {Reg::Bank::Out, Kind::Float, r - 'a'};
        else if (bank == 'o' && upperIn(r, 'D'))
            reg = {Reg::Bank::Out, Kind::Vec, r - 'A'};
        else
            return false;
        return true;
    }

    int componentIndex() {
        expect("[");
        if (tok_.t != Tok::T::Number || !(tok_.number == 0 || tok_.number == 1 || tok_.number == 2))
            fail("expected a component index 0, 1 or 2");
        const int c = int(tok_.number);
        advance();
        expect("]");
        return c;
    }

    void parseStatement() {
        if (tok_.t != Tok::T::Name) fail("expected an output or temporary register (oa, tA, ...)");
        Reg target{};
        if (!regOf(tok_.text, target) || target.bank == Reg::Bank::In)
            fail("only outputs (oa..od, oA..oD) and temporaries (ta..th, tA..tH) can be "
                 "assigned");
        advance();
        Calculator::Program::Statement st;
        st.target = target;
        Kind want = target.kind;
        if (isSym("[")) {
            if (target.kind != Kind::Vec) fail("only a vector register has components");
            st.component = componentIndex();
            want = Kind::Float;
        }
        expect("=");
        st.value = parseExpr();
        if (st.value->kind != want)
            fail(want == Kind::Float ? "a vector cannot be assigned to a float"
                                     : "a float cannot be assigned to a vector");
        if (target.bank == Reg::Bank::Out)
            program_.outUsed[(target.kind == Kind::Vec ? 4 : 0) + target.index] = true;
        program_.statements.push_back(std::move(st));
    }

    std::unique_ptr<Expr> make(Op op, Kind kind) {
        auto e = std::make_unique<Expr>();
        e->op = op;
        e->kind = kind;
        return e;
    }

    std::unique_ptr<Expr> parseExpr() {
        if (++depth_ > 200) fail("expression nested too deeply");
        std::unique_ptr<Expr> cond = parseOr();
        if (isSym("?")) {
            advance();
            auto e = make(Op::Cond, Kind::Float);
            std::unique_ptr<Expr> a = parseExpr();
            expect(":");
            std::unique_ptr<Expr> b = parseExpr();
            if (a->kind != b->kind) fail("both sides of ':' must be floats or both vectors");
            e->kind = a->kind;
            e->args.push_back(std::move(cond));
            e->args.push_back(std::move(a));
            e->args.push_back(std::move(b));
            --depth_;
            return e;
        }
        --depth_;
        return cond;
    }

    std::unique_ptr<Expr> binary(Op op, std::unique_ptr<Expr> l, std::unique_ptr<Expr> r) {
        Kind kind = Kind::Float;
        const bool lv = l->kind == Kind::Vec, rv = r->kind == Kind::Vec;
        switch (op) {
        case Op::Add:
        case Op::Sub:
            if (lv != rv) fail("'+' and '-' need two floats or two vectors");
            kind = l->kind;
            break;
        case Op::Mul:
            if (lv && rv) fail("two vectors cannot be multiplied (use dot or cross)");
            kind = (lv || rv) ? Kind::Vec : Kind::Float;
            break;
        case Op::Div:
            if (rv) fail("cannot divide by a vector");
            kind = l->kind;
            break;
        case Op::Mod:
        case Op::Lt:
        case Op::Gt:
        case Op::Le:
        case Op::Ge:
            if (lv || rv) fail("this operator needs floats");
            break;
        case Op::Eq:
        case Op::Ne:
            if (lv != rv) fail("'==' and '!=' compare two floats or two vectors");
            break;
        default:
            break;
        }
        auto e = make(op, kind);
        e->args.push_back(std::move(l));
        e->args.push_back(std::move(r));
        return e;
    }

    std::unique_ptr<Expr> parseOr() {
        auto l = parseAnd();
        while (isSym("||")) {
            advance();
            l = binary(Op::Or, std::move(l), parseAnd());
        }
        return l;
    }
    std::unique_ptr<Expr> parseAnd() {
        auto l = parseEq();
        while (isSym("&&")) {
            advance();
            l = binary(Op::And, std::move(l), parseEq());
        }
        return l;
    }
    std::unique_ptr<Expr> parseEq() {
        auto l = parseRel();
        while (isSym("==") || isSym("!=")) {
            const Op op = isSym("==") ? Op::Eq : Op::Ne;
            advance();
            l = binary(op, std::move(l), parseRel());
        }
        return l;
    }
    std::unique_ptr<Expr> parseRel() {
        auto l = parseAdd();
        while (isSym("<") || isSym(">") || isSym("<=") || isSym(">=")) {
            const Op op = isSym("<") ? Op::Lt : isSym(">") ? Op::Gt : isSym("<=") ? Op::Le : Op::Ge;
            advance();
            l = binary(op, std::move(l), parseAdd());
        }
        return l;
    }
    std::unique_ptr<Expr> parseAdd() {
        auto l = parseMul();
        while (isSym("+") || isSym("-")) {
            const Op op = isSym("+") ? Op::Add : Op::Sub;
            advance();
            l = binary(op, std::move(l), parseMul());
        }
        return l;
    }
    std::unique_ptr<Expr> parseMul() {
        auto l = parseUnary();
        while (isSym("*") || isSym("/") || isSym("%")) {
            const Op op = isSym("*") ? Op::Mul : isSym("/") ? Op::Div : Op::Mod;
            advance();
            l = binary(op, std::move(l), parseUnary());
        }
        return l;
    }
    std::unique_ptr<Expr> parseUnary() {
        if (isSym("-") || isSym("!")) {
            const bool neg = isSym("-");
            advance();
            if (++depth_ > 200) fail("expression nested too deeply");
            std::unique_ptr<Expr> x = parseUnary();
            --depth_;
            if (!neg && x->kind == Kind::Vec) fail("'!' needs a float");
            auto e = make(neg ? Op::Neg : Op::Not, neg ? x->kind : Kind::Float);
            e->args.push_back(std::move(x));
            return e;
        }
        std::unique_ptr<Expr> p = parsePrimary();
        if (isSym("[")) {
            if (p->kind != Kind::Vec) fail("only a vector has components");
            auto e = make(Op::Component, Kind::Float);
            e->component = componentIndex();
            e->args.push_back(std::move(p));
            return e;
        }
        return p;
    }

    std::vector<std::unique_ptr<Expr>> arguments(std::initializer_list<Kind> kinds,
                                                 const std::string& name) {
        expect("(");
        std::vector<std::unique_ptr<Expr>> args;
        bool first = true;
        for (Kind k : kinds) {
            if (!first) expect(",");
            first = false;
            std::unique_ptr<Expr> a = parseExpr();
            if (a->kind != k)
                fail(name + " takes " + (k == Kind::Float ? "a float" : "a vector") + " here");
            args.push_back(std::move(a));
        }
        expect(")");
        return args;
    }

    std::unique_ptr<Expr> parsePrimary() {
        if (tok_.t == Tok::T::Number) {
            auto e = make(Op::Number, Kind::Float);
            e->number = tok_.number;
            advance();
            return e;
        }
        if (isSym("(")) {
            advance();
            std::unique_ptr<Expr> e = parseExpr();
            expect(")");
            return e;
        }
        if (tok_.t != Tok::T::Name) fail("expected a value");
        const std::string name = tok_.text;
        static const std::pair<const char*, double> constants[] = {
            {"MAXFLOAT", FLT_MAX},
            {"MINFLOAT", FLT_MIN},
            {"M_E", std::numbers::e},
            {"M_LOG2E", std::numbers::log2e},
            {"M_LOG10E", std::numbers::log10e},
            {"M_LN2", std::numbers::ln2},
            {"M_LN10", std::numbers::ln10},
            {"M_PI", std::numbers::pi},
            {"M_PI_2", std::numbers::pi / 2},
            {"M_PI_4", std::numbers::pi / 4},
            {"M_1_PI", std::numbers::inv_pi},
            {"M_2_PI", 2 * std::numbers::inv_pi},
            {"M_2_SQRTPI", 2 * std::numbers::inv_sqrtpi},
            {"M_SQRT2", std::numbers::sqrt2},
            {"M_SQRT1_2", 1 / std::numbers::sqrt2}};
        for (const auto& [cname, value] : constants)
            if (name == cname) {
                advance();
                auto e = make(Op::Number, Kind::Float);
                e->number = double(float(value));
                return e;
            }
        Reg reg{};
        if (regOf(name, reg)) {
            advance();
            if (reg.bank == Reg::Bank::In)
                program_.inUsed[(reg.kind == Kind::Vec ? 8 : 0) + reg.index] = true;
            auto e = make(Op::Reg, reg.kind);
            e->reg = reg;
            return e;
        }
        static const std::pair<const char*, double (*)(double)> functions[] = {
            {"cos", [](double x) { return std::cos(x); }},
            {"sin", [](double x) { return std::sin(x); }},
            {"tan", [](double x) { return std::tan(x); }},
            {"acos", [](double x) { return std::acos(x); }},
            {"asin", [](double x) { return std::asin(x); }},
            {"atan", [](double x) { return std::atan(x); }},
            {"cosh", [](double x) { return std::cosh(x); }},
            {"sinh", [](double x) { return std::sinh(x); }},
            {"tanh", [](double x) { return std::tanh(x); }},
            {"sqrt", [](double x) { return std::sqrt(x); }},
            {"exp", [](double x) { return std::exp(x); }},
            {"log", [](double x) { return std::log(x); }},
            {"log10", [](double x) { return std::log10(x); }},
            {"ceil", [](double x) { return std::ceil(x); }},
            {"floor", [](double x) { return std::floor(x); }},
            {"fabs", [](double x) { return std::fabs(x); }},
            {"rand", [](double x) { return x; }}};
        for (const auto& [fname, fn] : functions)
            if (name == fname) {
                advance();
                auto e = make(Op::Func1, Kind::Float);
                e->func = fn;
                e->isRand = name == "rand";
                e->args = arguments({Kind::Float}, name);
                return e;
            }
        struct Special {
            const char* name;
            Op op;
            Kind result;
            std::initializer_list<Kind> args;
        };
        static const Special specials[] = {
            {"atan2", Op::Atan2, Kind::Float, {Kind::Float, Kind::Float}},
            {"pow", Op::Pow, Kind::Float, {Kind::Float, Kind::Float}},
            {"fmod", Op::Fmod, Kind::Float, {Kind::Float, Kind::Float}},
            {"length", Op::Length, Kind::Float, {Kind::Vec}},
            {"dot", Op::Dot, Kind::Float, {Kind::Vec, Kind::Vec}},
            {"cross", Op::Cross, Kind::Vec, {Kind::Vec, Kind::Vec}},
            {"normalize", Op::Normalize, Kind::Vec, {Kind::Vec}},
            {"vec3f", Op::Vec3f, Kind::Vec, {Kind::Float, Kind::Float, Kind::Float}}};
        for (const Special& s : specials)
            if (name == s.name) {
                advance();
                auto e = make(s.op, s.result);
                e->args = arguments(s.args, name);
                return e;
            }
        fail("unknown name");
    }

    const std::string& text_;
    Calculator::Program& program_;
    std::size_t pos_ = 0;
    Tok tok_;
    int depth_ = 0;
};

struct Registers {
    double in[8];
    glm::dvec3 inVec[8];
    double out[4];
    glm::dvec3 outVec[4];
    double tmp[8];
    glm::dvec3 tmpVec[8];
    std::uint64_t* random;
};

Value eval(const Expr& e, Registers& r) {
    auto f = [&](std::size_t i) { return eval(*e.args[i], r).f; };
    auto v = [&](std::size_t i) { return eval(*e.args[i], r).v; };
    Value out;
    switch (e.op) {
    case Op::Number:
        out.f = e.number;
        break;
    case Op::Reg: {
        const Reg& g = e.reg;
        if (g.kind == Kind::Float)
            out.f = g.bank == Reg::Bank::In    ? r.in[g.index]
                    : g.bank == Reg::Bank::Out ? r.out[g.index]
                                               : r.tmp[g.index];
        else
            out.v = g.bank == Reg::Bank::In    ? r.inVec[g.index]
                    : g.bank == Reg::Bank::Out ? r.outVec[g.index]
                                               : r.tmpVec[g.index];
        break;
    }
    case Op::Component:
        out.f = v(0)[e.component];
        break;
    case Op::Neg:
        if (e.kind == Kind::Vec)
            out.v = -v(0);
        else
            out.f = -f(0);
        break;
    case Op::Not:
        out.f = f(0) == 0.0 ? 1.0 : 0.0;
        break;
    case Op::Add:
    case Op::Sub: {
        const double s = e.op == Op::Add ? 1.0 : -1.0;
        if (e.kind == Kind::Vec)
            out.v = v(0) + s * v(1);
        else
            out.f = f(0) + s * f(1);
        break;
    }
    case Op::Mul:
        if (e.kind == Kind::Vec)
            out.v = e.args[0]->kind == Kind::Vec ? v(0) * f(1) : f(0) * v(1);
        else
            out.f = f(0) * f(1);
        break;
    case Op::Div:
        if (e.kind == Kind::Vec)
            out.v = v(0) / f(1);
        else
            out.f = f(0) / f(1);
        break;
    case Op::Mod:
    case Op::Fmod:
        out.f = std::fmod(f(0), f(1));
        break;
    case Op::Eq:
    case Op::Ne: {
        const bool same = e.args[0]->kind == Kind::Vec ? v(0) == v(1) : f(0) == f(1);
        out.f = (same == (e.op == Op::Eq)) ? 1.0 : 0.0;
        break;
    }
    case Op::Lt:
        out.f = f(0) < f(1);
        break;
    case Op::Gt:
        out.f = f(0) > f(1);
        break;
    case Op::Le:
        out.f = f(0) <= f(1);
        break;
    case Op::Ge:
        out.f = f(0) >= f(1);
        break;
    case Op::And:
        out.f = (f(0) != 0.0 && f(1) != 0.0) ? 1.0 : 0.0;
        break;
    case Op::Or:
        out.f = (f(0) != 0.0 || f(1) != 0.0) ? 1.0 : 0.0;
        break;
    case Op::Cond: {
        const Value c = eval(*e.args[0], r);
        const bool truth = e.args[0]->kind == Kind::Vec ? c.v != glm::dvec3(0.0) : c.f != 0.0;
        return eval(*e.args[truth ? 1 : 2], r);
    }
    case Op::Func1:
        if (e.isRand) {
            (void)f(0);
            // xorshift64*: the same sequence every run, so images and tests repeat.
            std::uint64_t& s = *r.random;
            s ^= s >> 12;
            s ^= s << 25;
            s ^= s >> 27;
            out.f = double((s * 0x2545F4914F6CDD1DULL) >> 11) / double(1ULL << 53);
        } else {
            out.f = e.func(f(0));
        }
        break;
    case Op::Atan2:
        out.f = std::atan2(f(0), f(1));
        break;
    case Op::Pow:
        out.f = std::pow(f(0), f(1));
        break;
    case Op::Length:
        out.f = glm::length(v(0));
        break;
    case Op::Dot:
        out.f = glm::dot(v(0), v(1));
        break;
    case Op::Cross:
        out.v = glm::cross(v(0), v(1));
        break;
    case Op::Normalize: {
        const glm::dvec3 x = v(0);
        const double len = glm::length(x);
        out.v = len > 0.0 ? x / len : x;
        break;
    }
    case Op::Vec3f:
        out.v = glm::dvec3(f(0), f(1), f(2));
        break;
    }
    return out;
}

} // namespace

Calculator::Calculator() = default;
Calculator::~Calculator() = default;

std::vector<Engine::OutputSpec> Calculator::outputSpecs() const {
    return {{"oa", "MFFloat"}, {"ob", "MFFloat"}, {"oc", "MFFloat"}, {"od", "MFFloat"},
            {"oA", "MFVec3f"}, {"oB", "MFVec3f"}, {"oC", "MFVec3f"}, {"oD", "MFVec3f"}};
}

void Calculator::check(const std::string& text) {
    Program program;
    Parser(text, program).parseAll();
}

void Calculator::compile() {
    if (program_ && compiledFrom_ == expression()) return;
    auto program = std::make_unique<Program>();
    for (const std::string& text : expression()) {
        Program one;
        Parser(text, one).parseAll();
        for (auto& st : one.statements)
            program->statements.push_back(std::move(st));
        for (int i = 0; i < 16; ++i)
            program->inUsed[i] = program->inUsed[i] || one.inUsed[i];
        for (int i = 0; i < 8; ++i)
            program->outUsed[i] = program->outUsed[i] || one.outUsed[i];
    }
    program_ = std::move(program);
    compiledFrom_ = expression();
}

void Calculator::readDone(const ReadContext&) {
    compile();
}

void Calculator::evaluate(const EngineContext&) {
    compile();
    const MFFloat* floats[8] = {&a, &b, &c, &d, &e, &f, &g, &h};
    const MFVec3f* vecs[8] = {&A, &B, &C, &D, &E, &F, &G, &H};
    std::size_t n = 0;
    for (int i = 0; i < 8; ++i) {
        if (program_->inUsed[i]) n = std::max(n, floats[i]->size());
        if (program_->inUsed[8 + i]) n = std::max(n, vecs[i]->size());
    }
    if (n == 0) n = 1;
    std::vector<float> outF[4];
    std::vector<glm::vec3> outV[4];
    for (std::size_t i = 0; i < n; ++i) {
        Registers r{};
        r.random = &random_;
        for (int k = 0; k < 8; ++k) {
            const auto& fv = floats[k]->getValues();
            r.in[k] = fv.empty() ? 0.0 : double(fv[std::min(i, fv.size() - 1)]);
            const auto& vv = vecs[k]->getValues();
            r.inVec[k] = vv.empty() ? glm::dvec3(0.0) : glm::dvec3(vv[std::min(i, vv.size() - 1)]);
        }
        for (const Program::Statement& st : program_->statements) {
            const Value value = eval(*st.value, r);
            const Reg& t = st.target;
            if (t.kind == Kind::Float) {
                (t.bank == Reg::Bank::Out ? r.out : r.tmp)[t.index] = value.f;
            } else {
                glm::dvec3& target = (t.bank == Reg::Bank::Out ? r.outVec : r.tmpVec)[t.index];
                if (st.component >= 0)
                    target[st.component] = value.f;
                else
                    target = value.v;
            }
        }
        for (int k = 0; k < 4; ++k) {
            outF[k].push_back(float(r.out[k]));
            outV[k].push_back(glm::vec3(r.outVec[k]));
        }
    }
    for (int k = 0; k < 4; ++k) {
        if (program_->outUsed[k]) setValues<MFFloat>(std::size_t(k), std::move(outF[k]));
        if (program_->outUsed[4 + k]) setValues<MFVec3f>(std::size_t(4 + k), std::move(outV[k]));
    }
}

} // namespace volsg
