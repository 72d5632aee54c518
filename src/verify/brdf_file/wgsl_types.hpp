// WGSL's types as the checker sees them (https://www.w3.org/TR/WGSL/#types): scalars, vectors,
// matrices and structures, the abstract numeric types of literals and constants (#abstract-types)
// with the automatic conversions WGSL makes from them and no other (#conversion-rank), and the
// values of const-expressions, computed as WGSL does: AbstractFloat in binary64, AbstractInt in 64
// bits, f32 in binary32, i32 and u32 modulo 2^32.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace verify::wgsl {

enum class scalar : std::uint8_t { abstract_int, abstract_float, f32, f16, i32, u32, boolean };

struct type {
    enum class kind : std::uint8_t { none, scalar, vector, matrix, structure, unsupported };
    kind k = kind::none;
    scalar s = scalar::f32;  // a scalar, or a vector's or matrix's element
    int n = 0;               // a vector's size, a matrix's columns
    int rows = 0;            // a matrix's rows
    int index = -1;          // a structure's declaration
    std::string spelled;     // a structure's name; an unsupported type as written
    bool operator==(const type& o) const {
        return k == o.k && (k == kind::none || k == kind::unsupported || (s == o.s && n == o.n && rows == o.rows && index == o.index));
    }
    bool operator!=(const type& o) const { return !(*this == o); }
};

type scalar_type(scalar s);
type vector_type(int n, scalar s);
type matrix_type(int columns, int rows, scalar s);

bool is_abstract(const type& t);
// A type a let, var, parameter or result of the subset may have: a concrete scalar but f16, a
// structure, or a vector or matrix of f32.
bool supported_type(const type& t);
bool is_float(scalar s);    // AbstractFloat, f32, f16
bool is_integer(scalar s);  // AbstractInt, i32, u32
bool numeric(const type& t);  // a number, or a vector or matrix of numbers
int components(const type& t);
type with_element(const type& t, scalar s);
// AbstractInt becomes i32, AbstractFloat f32 (#concretization): what let and var take.
type concretized(const type& t);
// `from` is `to`, or WGSL converts it automatically (only from an abstract type).
bool converts(const type& from, const type& to);
// The one type both convert to, if any (#overload-resolution-section: the lowest conversion rank).
bool join(const type& a, const type& b, type& out);

std::string type_name(const type& t);
// Why `from` does not convert to `to`, in parentheses, for a message.
std::string why_not(const type& from, const type& to);
// The type's name with its article, as messages read it: "an f32", "a vec3<f32>".
std::string a_type(const type& t);

// The value of a const-expression, component by component (a matrix column by column): exact
// for the integer types and binary64 for AbstractFloat (held in a long double, which holds both).
struct value {
    bool known = false;
    std::vector<long double> c;
};

// `v` of type `from` as `to` (a conversion WGSL makes, automatically or by a constructor); false
// and `why` where WGSL refuses it (an AbstractInt out of i32's range, an AbstractFloat beyond f32's).
bool convert_value(value& v, const type& from, const type& to, std::string& why);

// A value as GLSL text of type `t` (a literal, or a constructor of literals), on one line.
std::string glsl_literal(const value& v, const type& t);

// The GLSL type of a supported type (float, int, bool, vec3, mat3, or a structure's name).
std::string glsl_type(const type& t, const std::string& struct_name);

}  // namespace verify::wgsl
