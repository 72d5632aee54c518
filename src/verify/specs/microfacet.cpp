// microfacet: the committed tables of microfacet compositions (docs/microfacet.md).
#include "../table_spec.hpp"

#include "../microfacet_tables.hpp"

namespace verify {

table_spec microfacet_spec() {
    return {"microfacet",
            "microfacet compositions D/G/F: E(mu, alpha) of the reference compositions and the white furnace "
            "of their multiple-scattering compensations, E_avg(alpha), and every shortcut against the exact "
            "integrals (visibility terms, the EnvBRDFApprox fit, Monte Carlo bakers, Schlick's Fresnel)",
            {},
            [](const options& o) { return microfacet_tables(o.jobs); }};
}

}  // namespace verify
