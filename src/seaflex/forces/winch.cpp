#include "seaflex/forces/winch.hpp"

namespace seaflex {

Winch Winch::constant_rate(double rate, double start) {
  Winch w;
  w.rate_ = rate;
  w.start_ = start;
  return w;
}

Winch Winch::table(std::vector<double> times, std::vector<double> changes) {
  std::vector<Vec6> values;
  for (double c : changes) values.push_back((Vec6() << c, 0, 0, 0, 0, 0).finished());
  Winch w;
  w.table_ = std::make_shared<TableMotion>(std::move(times), std::move(values));
  return w;
}

double Winch::change(double t) const {
  if (table_) return table_->sample(t).x[0];
  return t > start_ ? rate_ * (t - start_) : 0.0;
}

double Winch::rate(double t) const {
  if (table_) return table_->sample(t).x_t[0];
  return t > start_ ? rate_ : 0.0;
}

}  // namespace seaflex
