// [brdf]
// [parameters.op]
// range = [0, 8]
// default = 0
//

// One operation a GPU leaves undefined per value of op (docs/brdf-code.md#gpu-undefined-operations),
// each where c = (N.L)(N.V) - 1/4 makes it so (for either direction held at 30 degrees: where the
// other's cosine is below 0.2887, or for asin above 0.6736), its result kept finite on the CPU (a NaN or Inf made 0) so
// that only the operation tells; op = 0 is a constant lobe with none of them.
float kept(float x)
{
    return x != x || abs(x) > 1.0e30 ? 0.0 : x;
}

vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)
{
    float c = dot(N, L) * dot(N, V) - 0.25;
    float r = 0.0;
    if (op == 1.0) r = pow(c, 2.0);                       // c < 0
    else if (op == 2.0) r = kept(sqrt(c));                // c < 0
    else if (op == 3.0) r = kept(inversesqrt(c));         // c <= 0
    else if (op == 4.0) r = kept(log(c)) + kept(log2(c)); // c <= 0
    else if (op == 5.0) r = kept(asin(3.0 * c));         // |3 c| > 1
    else if (op == 6.0) r = atan(c - c, c - c);           // everywhere
    else if (op == 7.0) r = kept(normalize(vec3(0.0) * c).x);  // everywhere
    else if (op == 8.0) r = kept(1.0 / (c - c));          // everywhere
    return vec3(0.1 + 0.001 * r);
}
