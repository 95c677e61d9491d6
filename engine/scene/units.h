// Photometric → radiometric conversion: the ONE place where glTF's photometric quantities
// become bounce's radiometric ones (see docs/units.md).
//
// Convention: a fixed luminous efficacy of kLumensPerWatt = 683 lm/W, applied to each
// linear-RGB channel independently, as if every channel were monochromatic light at 555 nm
// (the SI definition of the candela). So, per channel:
//   intensity  W/sr       = cd  / 683      (point and spot lights)
//   irradiance W/m²       = lux / 683      (directional lights)
//   radiance   W/(sr·m²)  = nit / 683      (emissive surfaces: emissiveFactor × strength)
// The conversion is linear and exactly invertible; conversions are done in double so that a
// value written as x·683 loads back as x to float precision.
// OBJ/MTL `Ke` is NOT converted: it is read as radiance in W/(sr·m²) directly.
#pragma once

namespace bounce {

inline constexpr double kLumensPerWatt = 683.0;  // lm/W at 555 nm (SI definition of the cd)

// Luminous intensity (cd = lm/sr) → radiant intensity (W/sr), and back.
constexpr double candelaToWattsPerSr(double candela) {
  return candela / kLumensPerWatt;
}
constexpr double wattsPerSrToCandela(double wattsPerSr) {
  return wattsPerSr * kLumensPerWatt;
}

// Illuminance (lux = lm/m²) → irradiance (W/m²), and back.
constexpr double luxToWattsPerM2(double lux) {
  return lux / kLumensPerWatt;
}
constexpr double wattsPerM2ToLux(double wattsPerM2) {
  return wattsPerM2 * kLumensPerWatt;
}

// Luminance (nit = cd/m²) → radiance (W/(sr·m²)), and back.
constexpr double nitsToRadiance(double nits) {
  return nits / kLumensPerWatt;
}
constexpr double radianceToNits(double radiance) {
  return radiance * kLumensPerWatt;
}

}  // namespace bounce
