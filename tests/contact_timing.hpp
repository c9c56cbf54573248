#pragma once
// How long two particles touch: steps a simulation until their overlap,
// read by `overlap()`, has come and gone, and returns the time between the
// crossings of zero, interpolated between steps (-1 where none was seen).
namespace vrut_test {

template <class Sim, class Overlap>
double contact_duration(Sim& sim, double dt, Overlap overlap, long max_steps = 200000) {
  double previous = overlap(), t_in = -1.0, t_out = -1.0;
  for (long s = 0; s < max_steps && t_out < 0.0; ++s) {
    sim.step(dt);
    const double now = overlap();
    if (previous <= 0.0 && now > 0.0) t_in = sim.time() - dt * now / (now - previous);
    if (previous > 0.0 && now <= 0.0) t_out = sim.time() - dt * now / (now - previous);
    previous = now;
  }
  return t_out < 0.0 ? -1.0 : t_out - t_in;
}

}  // namespace vrut_test
