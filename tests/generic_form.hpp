// A form with its lobe factor hidden, so that albedo<> takes the generic integral of albedo.hpp
// rather than the one in Blinn-Phong's lobe mass (lobe_albedo.hpp): the tests compare the two.
#pragma once

template <class Form>
struct generic_form : Form {
    static void lobe_factor();  // hides Form::lobe_factor: has_blinn_phong_lobe is false
};
