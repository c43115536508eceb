#include "duet/mps2_an386/plant_link.hpp"

#include "duet/cortex_m/interrupts.hpp"
#include "duet/cortex_m/semihosting.hpp"
#include "duet/hardware/hardware.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/mps2_an386/executive_port.hpp"

namespace duet::mps2_an386 {
namespace {

using link::FrameKind;
namespace semihosting = cortex_m::semihosting;

// Compared byte by byte: std::string_view's == may call memcmp, a library routine this code, which runs in the base
// tick's handler, keeps out of every interrupt's reach (the call-graph scan, ports/cortex-m/README.md).
bool same_name(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k] != b[k]) return false;
  }
  return true;
}

}  // namespace

// Interrupts masked and the cycles counted as the link's for as long as it exists.
class PlantLink::LinkSection {
 public:
  LinkSection() : saved_primask_(cortex_m::mask_interrupts()), started_(ExecutivePort::cycles()) {}
  ~LinkSection() {
    count();
    cortex_m::restore_interrupts(saved_primask_);
  }
  LinkSection(const LinkSection&) = delete;
  LinkSection& operator=(const LinkSection&) = delete;

  // Lets interrupts in while `run` does, its cycles not the link's, then masks them again.
  template <typename Function>
  void release_while(Function run) {
    count();
    cortex_m::enable_interrupts();
    run();
    cortex_m::disable_interrupts();
    started_ = ExecutivePort::cycles();
  }

 private:
  void count() const { cycles_spent_ += ExecutivePort::cycles() - started_; }

  std::uint32_t saved_primask_;
  std::uint32_t started_;
};

// Masked: the link may count cycles between the two reads, from a handler of any priority that preempts the caller.
std::uint32_t PlantLinkedPort::cycles() {
  const cortex_m::InterruptMask masked;
  return ExecutivePort::cycles() - PlantLink::cycles_spent();
}

bool PlantLink::connect(std::string_view to_plant, std::string_view from_plant, std::uint32_t base_period_ns) {
  const LinkSection section;
  // The plant holds its ends open, so neither open waits; this order matches the plant's in any case.
  to_plant_ = semihosting::open(to_plant, semihosting::FileMode::write_binary);
  from_plant_ = semihosting::open(from_plant, semihosting::FileMode::read_binary);
  if (to_plant_ < 0 || from_plant_ < 0) {
    error_.append("cannot open the pipes to and from the plant: ").append(to_plant).append(", ").append(from_plant);
    return false;
  }
  send(link::encode_hello(frame_, {link::protocol_version, link::LinkMode::lock_step, base_period_ns}));
  if (!expect(FrameKind::hello_ok)) return false;
  link::HelloOk hello_ok;
  if (link::parse(decoder_.payload(), hello_ok) != link::FrameError::none) {
    fail("the plant answered HELLO with a bad HELLO_OK");
  } else if (hello_ok.version != link::protocol_version) {
    TextBuffer<80> versions;
    versions.append(hello_ok.version).append("; this firmware speaks version ").append(link::protocol_version);
    fail("the plant answered HELLO with link protocol version ", versions.view());
  }
  return ok();
}

template <typename Element>
void PlantLink::write(std::string_view resource, std::span<const Element> values) {
  if (!ok()) return;
  const LinkSection section;
  const std::span<const std::uint8_t> frame = link::encode_write(frame_, resource, values);
  if (frame.empty()) return fail("a WRITE too long for the link's buffer: ", resource);
  send(frame);
}
// What hardware.hpp's calls write: an SPI transfer's bytes, an ADC sequence's length, a PWM duty (pins: send()).
template void PlantLink::write(std::string_view, std::span<const std::uint8_t>);
template void PlantLink::write(std::string_view, std::span<const std::uint16_t>);
template void PlantLink::write(std::string_view, std::span<const float>);

template <typename Element>
void PlantLink::read(std::string_view resource, std::span<Element> values) {
  for (Element& value : values) value = Element{};
  if (!ok()) return;
  const LinkSection section;
  constexpr link::ElementType type = link::element_type_of<Element>;
  if (values.size() > link::max_read_count(type) ||
      values.size() * link::element_size(type) + 3 > max_received_payload) {
    return fail("a READ too long for the link: ", resource);
  }
  const std::span<const std::uint8_t> frame =
      link::encode_read(frame_, resource, type, static_cast<std::uint16_t>(values.size()));
  if (frame.empty()) return fail("a READ too long for the link's buffer: ", resource);
  send(frame);
  if (!expect(FrameKind::values)) return;
  link::Values answer;
  if (link::parse(decoder_.payload(), answer) != link::FrameError::none || answer.values.type() != type ||
      answer.values.size() != values.size()) {
    return fail("the plant answered a READ with other values than it asked for: ", resource);
  }
  answer.values.copy_to(values);
}
// What hardware.hpp's calls read: a pin's level, received SPI bytes, ADC samples, a capture.
template void PlantLink::read(std::string_view, std::span<bool>);
template void PlantLink::read(std::string_view, std::span<std::uint8_t>);
template void PlantLink::read(std::string_view, std::span<std::uint16_t>);
template void PlantLink::read(std::string_view, std::span<std::uint32_t>);

void PlantLink::tick(std::uint64_t tick) {
  if (!ok()) return;
  LinkSection section;
  send(link::encode_tick(frame_, tick));
  while (receive()) {
    if (decoder_.kind() == FrameKind::tick_done) return;
    link::Interrupt interrupt;
    if (decoder_.kind() != FrameKind::interrupt ||
        link::parse(decoder_.payload(), interrupt) != link::FrameError::none) {
      return fail("the plant sent something else than INTERRUPT or TICK_DONE during a TICK");
    }
    if (!raise(interrupt.name, section)) return;
    send(link::encode_empty(frame_, FrameKind::interrupt_done));
  }
}

void PlantLink::bye() {
  if (!ok()) return;
  const LinkSection section;
  send(link::encode_empty(frame_, FrameKind::bye));
  flush();
}

// Lets the interrupt's task run: its cycles count and interrupts are unmasked for as long as it takes, which is at once
// and to its end, since the task is more urgent than whoever ticks. The task's own READ and WRITE frames go out
// meanwhile, as the protocol wants them: before INTERRUPT_DONE.
bool PlantLink::raise(std::string_view name, LinkSection& section) {
  for (const PlantInterrupt& interrupt : plant_interrupts) {
    if (!same_name(interrupt.name, name)) continue;
    section.release_while([line = interrupt.line] {
      cortex_m::set_interrupt_pending(line);
      asm volatile("isb" ::: "memory");  // the pended interrupt is taken here
    });
    return true;
  }
  fail("the plant raised an interrupt this board has no line for: ", name);
  return false;
}

void PlantLink::send_pin_writes() {
  const LinkSection section;
  queue_pin_writes();
}

void PlantLink::send(std::span<const std::uint8_t> frame) {
  queue_pin_writes();
  queue(frame);
}

void PlantLink::queue(std::span<const std::uint8_t> frame) {
  static_assert(outgoing_capacity >= sizeof frame_, "a frame fits an empty buffer");
  if (outgoing_size_ + frame.size() > outgoing_capacity) flush();
  for (const std::uint8_t byte : frame) outgoing_[outgoing_size_++] = byte;
}

// Each as the WRITE of one bool, in the order written. Not in frame_: send() queues them before the frame there.
// Under the link's section, which masks the interrupts whose tasks add to them.
void PlantLink::queue_pin_writes() {
  hardware::PlantPinWrites& writes = hardware::plant_pin_writes;
  for (std::size_t k = 0; k < writes.count && ok(); ++k) {
    std::uint8_t pin_frame[link::header_size + 64];
    const std::span<const std::uint8_t> frame =
        link::encode_write(pin_frame, writes.pins[k]->resource_name(), std::span<const bool>{&writes.levels[k], 1});
    if (frame.empty()) {
      fail("a pin's WRITE too long for the link's buffer: ", writes.pins[k]->resource_name());
    } else {
      queue(frame);
    }
  }
  writes.count = 0;
}

void PlantLink::flush() {
  const std::span<const std::uint8_t> pending = std::span{outgoing_}.first(outgoing_size_);
  outgoing_size_ = 0;
  if (to_plant_ < 0 || pending.empty()) return;
  if (semihosting::write(to_plant_, pending) != pending.size()) {
    semihosting::close(to_plant_);
    to_plant_ = -1;  // no ERROR frame can follow
    fail("the plant closed its pipe");
  }
}

bool PlantLink::read_more() {
  incoming_begin_ = 0;
  incoming_end_ = semihosting::read(from_plant_, incoming_);
  if (incoming_end_ == 0) fail("the plant closed its pipe");
  return incoming_end_ != 0;
}

bool PlantLink::receive() {
  flush();
  if (!ok()) return false;
  link::DecodeStatus status = link::DecodeStatus::need_more;
  while (status == link::DecodeStatus::need_more) {
    // Never an empty feed: the decoder would give the frame it last completed again.
    if (incoming_begin_ == incoming_end_ && !read_more()) return false;
    const auto fed = decoder_.feed(std::span{incoming_}.subspan(incoming_begin_, incoming_end_ - incoming_begin_));
    incoming_begin_ += fed.used;
    status = fed.status;
  }
  if (status != link::DecodeStatus::frame) {
    fail("the plant sent a bad frame: ", link::describe(decoder_.error()));
    return false;
  }
  if (decoder_.kind() == FrameKind::error) {
    link::ErrorText text;
    static_cast<void>(link::parse(decoder_.payload(), text));
    fail("the plant reported an error: ", text.text);
    return false;
  }
  return true;
}

bool PlantLink::expect(FrameKind kind) {
  if (!receive()) return false;
  if (decoder_.kind() == kind) return true;
  fail("the plant sent an unexpected frame: ", link::kind_name(decoder_.kind()));
  return false;
}

void PlantLink::fail(std::string_view what, std::string_view detail) {
  if (!ok()) return;
  error_.append(what).append(detail);
  // Tell the plant, so that it ends the session instead of waiting for a frame that will not come (the pins written
  // meanwhile no longer matter).
  queue(link::encode_error(frame_, error_.view()));
  flush();
}

}  // namespace duet::mps2_an386
