#include "duet/link/channel.hpp"

#include <utility>

namespace duet::link {
namespace {

std::string quoted(std::string_view name) { return "'" + std::string{name} + "'"; }

Status check_name(std::string_view what, std::string_view name) {
  if (name.empty()) return Failure{"cannot send " + std::string{what} + ": the name is empty"};
  if (name.size() > max_name) {
    return Failure{"cannot send " + std::string{what} + " " + quoted(name.substr(0, 40)) + "...: the name has " +
                   std::to_string(name.size()) + " bytes, at most " + std::to_string(max_name) + " fit"};
  }
  return done();
}

std::string hex_byte(std::uint8_t byte) {
  constexpr char digits[] = "0123456789ABCDEF";
  return std::string{"0x"} + digits[byte >> 4U] + digits[byte & 0xFU];
}

}  // namespace

Channel::Channel(Stream& stream, std::string peer) : stream_(stream), peer_(std::move(peer)) {}

template <typename Encode>
Status Channel::queue(FrameKind kind, Encode&& encode) {
  for (;;) {
    const std::span<const std::uint8_t> frame = encode(std::span<std::uint8_t>{out_}.subspan(queued_));
    if (!frame.empty()) {
      queued_ += frame.size();
      ++frames_sent_;
      return done();
    }
    if (queued_ == 0)
      return Failure{std::string{"cannot send "} + std::string{kind_name(kind)} + ": it does not fit in a frame"};
    if (Status flushed = flush(); !flushed) return flushed;
  }
}

Status Channel::send_hello(const Hello& hello) {
  return queue(FrameKind::hello, [&](std::span<std::uint8_t> buffer) { return encode_hello(buffer, hello); });
}

Status Channel::send_hello_ok(const HelloOk& hello_ok) {
  return queue(FrameKind::hello_ok, [&](std::span<std::uint8_t> buffer) { return encode_hello_ok(buffer, hello_ok); });
}

Status Channel::send_write(std::string_view resource, std::span<const double> values) {
  if (Status named = check_name("WRITE", resource); !named) return named;
  constexpr std::size_t size = element_size(ElementType::f64);
  if (1 + resource.size() + 3 + values.size() * size > max_payload) {
    return Failure{"cannot send WRITE " + quoted(resource) + " of " + std::to_string(values.size()) +
                   " values: a frame holds " + std::to_string((max_payload - 4 - resource.size()) / size) +
                   " with this name"};
  }
  return queue(FrameKind::write,
               [&](std::span<std::uint8_t> buffer) { return encode_write(buffer, resource, values); });
}

Status Channel::send_read(std::string_view resource, ElementType type, std::size_t count) {
  if (Status named = check_name("READ", resource); !named) return named;
  if (count > max_read_count(type)) {
    return Failure{"cannot send READ " + quoted(resource) + " of " + std::to_string(count) + " " +
                   std::string{element_type_name(type)} + " values: at most " + std::to_string(max_read_count(type)) +
                   " fit in the VALUES that answers it"};
  }
  return queue(FrameKind::read, [&](std::span<std::uint8_t> buffer) {
    return encode_read(buffer, resource, type, static_cast<std::uint16_t>(count));
  });
}

template <typename T>
Status Channel::send_values(std::span<const T> values) {
  return queue(FrameKind::values, [&](std::span<std::uint8_t> buffer) { return encode_values(buffer, values); });
}
template Status Channel::send_values(std::span<const bool>);
template Status Channel::send_values(std::span<const std::uint8_t>);
template Status Channel::send_values(std::span<const std::uint16_t>);
template Status Channel::send_values(std::span<const std::uint32_t>);
template Status Channel::send_values(std::span<const float>);
template Status Channel::send_values(std::span<const double>);

Status Channel::send_tick(std::uint64_t tick) {
  return queue(FrameKind::tick, [&](std::span<std::uint8_t> buffer) { return encode_tick(buffer, tick); });
}

Status Channel::send_interrupt(std::string_view name) {
  if (Status named = check_name("INTERRUPT", name); !named) return named;
  return queue(FrameKind::interrupt, [&](std::span<std::uint8_t> buffer) { return encode_interrupt(buffer, name); });
}

Status Channel::send_empty(FrameKind kind) {
  return queue(kind, [&](std::span<std::uint8_t> buffer) { return encode_empty(buffer, kind); });
}

Status Channel::flush() {
  if (queued_ == 0) return done();
  const std::size_t size = std::exchange(queued_, 0);
  if (Status written = stream_.write_all(std::span<const std::uint8_t>{out_}.first(size)); !written) {
    return Failure{"link to " + peer_ + ": " + written.error()};
  }
  return done();
}

Result<std::optional<ReceivedFrame>> Channel::receive(std::string_view awaiting) {
  if (Status flushed = flush(); !flushed) return Failure{flushed.error()};
  const auto waiting = [awaiting] { return " while awaiting " + std::string{awaiting}; };  // for failures only
  for (;;) {
    if (in_begin_ < in_end_) {
      const auto fed = decoder_.feed(std::span<const std::uint8_t>{in_}.subspan(in_begin_, in_end_ - in_begin_));
      in_begin_ += fed.used;
      if (fed.status == DecodeStatus::frame) {
        ++frames_received_;
        return std::optional<ReceivedFrame>{ReceivedFrame{decoder_.kind(), decoder_.payload()}};
      }
      if (fed.status == DecodeStatus::error) return fail(bad_frame() + waiting());
    }
    in_begin_ = in_end_ = 0;
    auto got = stream_.read_some(in_);
    if (!got) return fail("link to " + peer_ + ": " + got.error() + waiting());
    if (got.value() == 0) {
      if (decoder_.partial() == 0) return std::optional<ReceivedFrame>{};
      return Failure{cut_frame() + waiting()};
    }
    in_end_ = got.value();
  }
}

std::string Channel::bad_frame() const {
  const std::uint8_t kind = decoder_.partial_kind();
  std::string message = peer_ + " sent a bad frame (" + std::string{describe(decoder_.error())};
  if (decoder_.error() == FrameError::unknown_kind) {
    message += " " + hex_byte(kind);
  } else {
    message += std::string{": "} + std::string{kind_name(static_cast<FrameKind>(kind))} + " announcing " +
               std::to_string(decoder_.announced()) + " bytes";
  }
  return message + ")";
}

std::string Channel::cut_frame() const {
  const std::string total = decoder_.partial() >= header_size ? std::to_string(header_size + decoder_.announced())
                                                              : "at least " + std::to_string(header_size);
  return peer_ + " closed the link in the middle of a " +
         std::string{kind_name(static_cast<FrameKind>(decoder_.partial_kind()))} + " frame (" +
         std::to_string(decoder_.partial()) + " of " + total + " bytes)";
}

Failure Channel::fail(const std::string& message) {
  queued_ = 0;  // what was waiting to go no longer matters
  const auto frame = encode_error(out_, message);
  (void)stream_.write_all(frame);
  return Failure{message};
}

Failure Channel::peer_failure(const std::string& what) const { return Failure{peer_ + " " + what}; }

}  // namespace duet::link
