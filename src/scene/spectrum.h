#pragma once
// Dispersion: the wavelengths a path can carry and how one converts back to RGB.
//
// A path that meets a dispersive glass samples one wavelength uniformly in [kMin, kMax] and from then
// on sees that wavelength's index of refraction (hero-wavelength style with a single wavelength). Its
// RGB throughput is multiplied by w(lambda) / p(lambda), where each channel's w is a Gaussian
// normalised to integrate to 1 over the range: the expectation over lambda is then exactly 1 per
// channel, so no colour is gained or lost on average (white light stays white), while each single
// wavelength shows its own hue.
#include <glm/glm.hpp>

namespace fp::spectrum {

constexpr float kMinNm = 380.0f, kMaxNm = 720.0f;
constexpr glm::vec3 kCentreNm{600.0f, 545.0f, 450.0f};  // red, green, blue responses
constexpr glm::vec3 kWidthNm{40.0f, 35.0f, 30.0f};

// 1 / integral over [kMin, kMax] of each channel's Gaussian, by numerical integration.
glm::vec3 normalisation();

// Cauchy's equation n(lambda) = A + B / lambda^2 fitted to an index at the d line (587.6 nm) and an Abbe
// number V = (n_d - 1) / (n_F - n_C), with F = 486.1 nm and C = 656.3 nm. Returns (A, B), B in nm^2.
glm::vec2 cauchyFromAbbe(float indexD, float abbeNumber);

}  // namespace fp::spectrum
