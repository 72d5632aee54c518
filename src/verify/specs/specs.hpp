// The spec of each table, one function per file of this folder (registry.cpp lists them).
#pragma once
#include "../table_spec.hpp"

namespace verify {

table_spec zoo_spec();
table_spec bounds_spec();
table_spec enclosures_spec();
table_spec proofs_spec();
table_spec energy_spec();
table_spec microfacet_spec();
table_spec irradiance_spec();
table_spec ndf_spec();
table_spec shader_precision_spec();
table_spec brdf_code_spec();
table_spec code_audit_spec();
table_spec stability_spec();
table_spec audit_spec();

}  // namespace verify
