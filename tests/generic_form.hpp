// A form with its shortcuts hidden, so that albedo<> takes the plain generic integral of
// albedo.hpp: not the one in Blinn-Phong's lobe mass (lobe_albedo.hpp), and not the smoothing
// variable for Ward's 1/sqrt(N.V) at the horizon. The tests compare the two.
#pragma once

template <class Form>
struct generic_form : Form {
    static void lobe_factor();                      // hides Form::lobe_factor: has_blinn_phong_lobe is false
    static constexpr bool inverse_sqrt_nv = false;  // hides Form::inverse_sqrt_nv: sqrt_at_horizon is false
};
