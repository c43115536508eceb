#pragma once
// Disturbances asked for from other threads (the dashboard's Disturb box, a script) while a plant is served, handed
// to the plant on its own thread at the start of its next advance(), whose time they act from. So the plant stays
// single-threaded and a run stays a function of model times: a disturbance applied at t is the one a scenario would
// have planned for t. Every one applied is kept with its time, so that a run can be told and repeated.

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "duet/plant/plant.hpp"
#include "duet/support/result.hpp"

namespace duet::plant {

struct AppliedDisturbance {
  Disturbance disturbance;
  double time_s = 0;  // the model time it acts from
};

// Whether `disturbance` is one of `offered`, with a value within limits for each argument; the failure names the
// problem ("push: force_n = 80 N is outside -50 to 50 N").
[[nodiscard]] Status check_disturbance(const std::vector<DisturbanceKind>& offered, const Disturbance& disturbance);

class PlantControls {
 public:
  using Ticket = std::uint64_t;
  // Called once per accepted request, unless withdrawn: with the applied disturbance (on the plant's thread), or with
  // why it never will be (the plant stopped being served first).
  using Answer = std::function<void(const Result<AppliedDisturbance>&)>;

  explicit PlantControls(std::vector<DisturbanceKind> offered);
  PlantControls(const PlantControls&) = delete;
  PlantControls& operator=(const PlantControls&) = delete;
  ~PlantControls();

  [[nodiscard]] const std::vector<DisturbanceKind>& offered() const { return offered_; }

  // Any thread. Checks the request (check_disturbance) and that a plant is served, then queues it for that plant's
  // next advance(). The failure says why it was refused; `answer` is then never called.
  [[nodiscard]] Result<Ticket> request(Disturbance disturbance, Answer answer);
  // Any thread. Gives up on a request that has not been applied (its answer is never called): true; false when it
  // was applied or answered already.
  bool withdraw(Ticket ticket);
  // Any thread. Every disturbance applied so far, in order.
  [[nodiscard]] std::vector<AppliedDisturbance> applied() const;

 private:
  friend class ControlledPlant;
  struct Waiting {
    Ticket ticket = 0;
    Disturbance disturbance;
    Answer answer;
  };
  void attach();
  void detach();
  // On the plant's thread: hands the waiting requests to `plant` at `time_s`, then answers them.
  void apply(Plant& plant, double time_s);

  const std::vector<DisturbanceKind> offered_;
  mutable std::mutex mutex_;
  bool served_ = false;
  Ticket next_ticket_ = 1;
  std::vector<Waiting> waiting_;
  std::vector<AppliedDisturbance> applied_;
};

// A served plant that takes its disturbances from `controls`: while it exists, `controls` accepts requests for it.
// The rest of its calls go to the plant behind it.
class ControlledPlant final : public Plant {
 public:
  ControlledPlant(std::unique_ptr<Plant> behind, PlantControls& controls);
  // Requests not applied yet are answered: the plant is no longer served.
  ~ControlledPlant() override;

  [[nodiscard]] Status start(double base_period_s) override { return behind_->start(base_period_s); }
  void advance(double time_s, const RaiseInterrupt& raise) override;
  void write(std::string_view resource, std::span<const double> values) override { behind_->write(resource, values); }
  void read(std::string_view resource, std::span<double> values) override { behind_->read(resource, values); }
  [[nodiscard]] std::vector<Observable> observables() const override { return behind_->observables(); }
  void observe(std::span<double> values) const override { behind_->observe(values); }
  [[nodiscard]] std::vector<DisturbanceKind> disturbances() const override { return behind_->disturbances(); }
  void disturb(const Disturbance& disturbance, double time_s) override { behind_->disturb(disturbance, time_s); }
  [[nodiscard]] std::optional<Halt> halted() const override { return behind_->halted(); }

 private:
  std::unique_ptr<Plant> behind_;
  PlantControls& controls_;
};

}  // namespace duet::plant
