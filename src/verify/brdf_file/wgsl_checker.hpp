// The checker of a WGSL module (wgsl.hpp) and the GLSL it writes as it goes: what it knows of
// names, expressions and statements. Declarations are checked from the BRDF function outwards, as
// they are reached: what the BRDF does not reach is read but neither checked nor translated (an
// engine's file holds entry points and bindings beside its lighting functions).
//   wgsl_check.cpp        the module: names, declarations, the BRDF's signature, the output
//   wgsl_check_types.cpp  types as written, and the constructors of values
//   wgsl_check_expr.cpp   expressions and their operators, with the values of const-expressions
//   wgsl_builtins.cpp     the built-in functions of the subset
//   wgsl_check_stmt.cpp   statements, scopes and behaviours (#behaviors)
//   wgsl_helpers.cpp      the GLSL functions the translation adds (WGSL's integer division, ...)
#pragma once
#include <map>
#include <set>
#include <string>
#include <vector>

#include "brdf_file.hpp"
#include "wgsl_syntax.hpp"
#include "wgsl_types.hpp"

namespace verify::wgsl {

// What a name denotes.
struct binding {
    enum class kind { let, var, constant, function, structure, alias, parameter, uniform_struct };
    kind k = kind::let;
    type t;
    std::string glsl;   // its GLSL spelling (a module const of a concrete type is a call: NAME())
    bool constant = false;
    value v;            // a constant's value, when known
    int decl = -1;      // its module-scope declaration
    int line = 0;
};

// A checked expression.
struct typed {
    type t;
    bool constant = false;  // a const-expression (#const-expr)
    value v;                // its value, when known (always for an abstract type)
    std::string text;       // GLSL (for a concrete type)
    bool reference = false; // names a var (or a part of one that may be assigned)
    std::string root;       // the variable it is part of
    bool swizzle = false;   // a swizzle of several components: a value, never assigned
    int line = 0;
};

struct piece {
    int line;
    std::string text;
};

enum behavior : unsigned { next = 1, returns = 2, breaks = 4, continues = 8 };

class checker {
public:
    checker(const shader_source& s, const module& m, std::string prefix);
    std::string run();  // the GLSL; throws bad_input
    std::string entry_glsl() const { return mangled(s_.function); }

private:
    const shader_source& s_;
    const module& m_;
    std::string prefix_;
    std::map<std::string, int> module_names_;
    std::vector<int> state_;            // per declaration: 0 unseen, 1 being checked, 2 checked
    std::vector<binding> decl_binding_;
    std::vector<std::vector<type>> signature_;  // a function's parameter types, then its return type
    std::vector<std::vector<piece>> out_;       // the GLSL of each declaration
    std::vector<int> struct_order_;             // structures in the order GLSL needs them
    std::set<std::string> helpers_;             // the helper functions used
    std::vector<std::string> prototypes_;       // of the functions reached and the concrete constants
    std::map<std::string, binding> parameters_; // the header's
    int module_depth_ = 0;
    int shadow_count_ = 0;

    // the function being checked
    std::vector<std::map<std::string, binding>> scopes_;
    type return_type_;
    bool has_return_type_ = false;
    bool splat_return_ = false;  // the BRDF's f32, returned as GLSL's vec3 of it
    int loop_depth_ = 0;
    bool in_continuing_ = false;
    std::vector<bool> loop_continued_;
    std::vector<piece>* pieces_ = nullptr;
    int current_ = -1;

    [[noreturn]] void fail(int line, const std::string& what) const;
    std::string mangled(const std::string& name) const { return prefix_ + "u" + name; }
    const expr& ex(int e) const { return m_.exprs.at(static_cast<std::size_t>(e)); }
    const stmt& st(int s) const { return m_.stmts.at(static_cast<std::size_t>(s)); }
    void emit(int line, const std::string& text) { pieces_->push_back({line, text}); }

    // wgsl_check.cpp
    void declare_module_names();
    const binding* lookup(const std::string& name, int line);
    const binding& module_binding(int d, int line);
    void check_function(int d);
    void check_signature(int d);
    void check_struct(int d);
    void check_const(int d);
    void check_var(int d, int use);
    void check_entry();
    void check_directives();
    std::string assemble();
    std::string new_local(const std::string& name);

    // wgsl_check_types.cpp
    type resolve_type(int e);
    type predeclared_type(const expr& x);
    typed construct(const expr& call, const type& t, std::vector<typed>& args);
    typed construct_inferred(const expr& call, std::vector<typed>& args);
    typed convert_scalar(const expr& call, const type& t, typed& a);
    std::string zero_text(const type& t);
    std::string struct_glsl(const type& t) const;
    std::string maker(int struct_decl);

    // wgsl_check_expr.cpp
    typed check(int e);
    std::string as(const typed& x, const type& to, int line);
    typed literal(const expr& x);
    typed name(const expr& x);
    typed call(const expr& x);
    typed index(const expr& x);
    typed member(const expr& x);
    typed uniform_member(const expr& x, const binding& u);
    typed unary(const expr& x);
    typed binary(const expr& x);
    typed arithmetic(const std::string& op, typed a, typed b, int line);
    typed matrix_product(typed a, typed b, int line);
    typed comparison(const std::string& op, typed a, typed b, int line);
    void fold(typed& r, const std::string& op, const typed& a, const typed& b, int line);
    std::string operator_text(const std::string& op, const typed& r, const std::string& a, const std::string& b);

    // wgsl_builtins.cpp
    typed builtin(const expr& x, std::vector<typed>& args);
    type builtin_type(const expr& x, int shape, const std::vector<typed>& args, std::vector<type>& params);
    void builtin_value(const expr& x, int shape, const std::vector<typed>& converted, typed& r);
    bool is_builtin(const std::string& name) const;

    // wgsl_check_stmt.cpp
    unsigned statement(int s);
    unsigned statements(const std::vector<int>& list);
    unsigned block(int s, bool new_scope = true);
    unsigned if_statement(int s);
    unsigned loop_statement(int s);
    unsigned for_statement(int s);
    unsigned while_statement(int s);
    std::string simple(int s);   // a declaration, assignment, increment or call, without its ';'
    std::string declaration(const stmt& x);
    std::string assignment(const stmt& x);
    typed condition(int e, const char* what);
    void declare(const std::string& name, binding b, int line);
};

// wgsl_helpers.cpp: the GLSL text of a helper function by its name (wgsl_helpers.cpp lists them),
// with `p` the translation's prefix.
std::string helper_text(const std::string& helper, const std::string& p);
std::vector<std::string> helper_dependencies(const std::string& helper);

}  // namespace verify::wgsl
