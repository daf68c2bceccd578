// KHR_materials_iridescence's thin-film Fresnel, Firid: a film of index `filmIor` and `thickness`
// nanometres over a base of normal-incidence reflectance baseF0, seen at cos(theta1) = cosTheta.
// Twin of core/shading/ThinFilm.cpp iridescenceFresnel, term by term (the extension's Implementation
// Notes; docs/shading.md, "Iridescence"); the caller clamps the result to [0, 1].
// Needs brdf_fresnel.glsl (F_Schlick) and common_math.glsl.

// Linear Rec.709 from CIE XYZ (columns X, Y, Z).
const mat3 kXyzToRec709 = mat3(3.2404542, -0.9692660, 0.0556434, -1.5371385, 1.8760108, -0.2040259, -0.4985314,
                               0.0415560, 1.0572252);
// The film fades to the outside's index below this thickness (core kThinFilmFadeThickness).
const float kThinFilmFadeThickness = 0.03;
// The base counts as less dense than the film only below eta2 - this (core kThinFilmIndexTolerance):
// equal indices round differently in float and double.
const float kThinFilmIndexTolerance = 1e-4;

// The colour matching functions' fitted Fourier transform at the path difference `opd` (nm), each
// XYZ row shifted by its component of `shift`, in linear Rec.709 (the extension's evalSensitivity;
// its amplitudes val sqrt(2 pi var) divided by the normalisation 1.0685e-7 first, to stay far from
// float's small numbers).
vec3 iridescenceSensitivity(float opd, vec3 shift)
{
    float phase = TWO_PI * opd * 1e-9;
    const vec3 val = vec3(5.4856e-13, 4.4201e-13, 5.2481e-13) / 1.0685e-7;
    const vec3 pos = vec3(1.6810e+06, 1.7953e+06, 2.2084e+06);
    const vec3 var = vec3(4.3278e+09, 9.3046e+09, 6.6121e+09);
    vec3 xyz = val * sqrt(TWO_PI * var) * cos(pos * phase + shift) * exp(-phase * phase * var);
    xyz.x += 9.7470e-14 / 1.0685e-7 * sqrt(TWO_PI * 4.5282e+09) * cos(2.2399e+06 * phase + shift.x)
             * exp(-4.5282e+09 * phase * phase);
    return kXyzToRec709 * xyz;
}

vec3 iridescenceFresnel(float filmIor, vec3 baseF0, float thickness, float cosTheta)
{
    float d = max(thickness, 0.0);
    float eta2 = mix(1.0, max(filmIor, 1.0), smoothstep(0.0, kThinFilmFadeThickness, d));
    float cos1 = saturate(cosTheta);
    float sin2Theta2 = (1.0 - cos1 * cos1) / (eta2 * eta2);
    float cos2Theta2 = 1.0 - sin2Theta2;
    if (cos2Theta2 < 0.0)
        return vec3(1.0); // the film reflects everything
    float cos2 = sqrt(cos2Theta2);
    float r0 = (eta2 - 1.0) / (eta2 + 1.0);
    float R12 = F_Schlick(r0 * r0, 1.0, cos1);
    float T121 = 1.0 - R12;
    float phi12 = eta2 < 1.0 ? PI : 0.0;
    float phi21 = PI - phi12;
    float opd = 2.0 * eta2 * d * cos2;

    vec3 sqrtF0 = sqrt(clamp(baseF0, 0.0, 0.9999));
    vec3 eta3 = (1.0 + sqrtF0) / (1.0 - sqrtF0);
    vec3 r1 = (eta3 - eta2) / (eta3 + eta2);
    vec3 R23 = F_Schlick(r1 * r1, 1.0, cos2);
    float denser = eta2 - kThinFilmIndexTolerance;
    vec3 phi23 = vec3(eta3.x < denser ? PI : 0.0, eta3.y < denser ? PI : 0.0, eta3.z < denser ? PI : 0.0);
    vec3 phi = vec3(phi21) + phi23;
    vec3 R123 = clamp(R12 * R23, 1e-5, 0.9999);
    vec3 r123 = sqrt(R123);
    vec3 Rs = T121 * T121 * R23 / (vec3(1.0) - R123);

    vec3 reflectance = R12 + Rs;
    vec3 cm = Rs - T121;
    for (int m = 1; m <= 2; ++m) {
        cm *= r123;
        reflectance += cm * 2.0 * iridescenceSensitivity(float(m) * opd, float(m) * phi);
    }
    return max(reflectance, vec3(0.0));
}
