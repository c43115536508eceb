#include "duet/rpmsg/device.hpp"

#include <cstring>

#include "little_endian.hpp"

namespace duet::rpmsg {

using little_endian::get16;
using little_endian::get32;
using little_endian::put16;
using little_endian::put32;

bool Device::send_from(std::uint32_t source, std::uint32_t destination, std::span<const std::uint8_t> first,
                       std::span<const std::uint8_t> second) {
  DeviceVring& ring = *configuration_.transmit;
  const auto buffer = ring.take();
  if (!buffer) return false;
  const std::size_t length = first.size() + second.size();
  if (buffer->length < header_size + length) {  // a buffer too small for what we send: give it back unused
    ring.give_back(buffer->head, 0);
    return false;
  }
  std::uint8_t* bytes = configuration_.buffer_at(buffer->address);
  put32(bytes, source);
  put32(bytes + 4, destination);
  put32(bytes + 8, 0);
  put16(bytes + 12, static_cast<std::uint16_t>(length));
  put16(bytes + 14, 0);
  if (!first.empty()) std::memcpy(bytes + header_size, first.data(), first.size());
  if (!second.empty()) std::memcpy(bytes + header_size + first.size(), second.data(), second.size());
  ring.give_back(buffer->head, static_cast<std::uint32_t>(header_size + length));
  if (ring.driver_wants_interrupt()) configuration_.notify(0);
  return true;
}

bool Device::announce() {
  for (; announced_ < configuration_.endpoints.size(); ++announced_) {
    const Endpoint& endpoint = configuration_.endpoints[announced_];
    std::uint8_t message[name_size + 8] = {};
    for (std::size_t at = 0; at + 1 < name_size && endpoint.name[at] != '\0'; ++at)
      message[at] = static_cast<std::uint8_t>(endpoint.name[at]);
    put32(message + name_size, endpoint.local);
    put32(message + name_size + 4, 0);  // create
    if (!send_from(endpoint.local, name_service_address, message)) return false;
  }
  return true;
}

SendResult Device::send(Endpoint& endpoint, std::span<const std::uint8_t> payload) {
  if (endpoint.remote == 0) return SendResult::no_remote_yet;
  if (payload.size() > 512 - header_size) return SendResult::too_long;
  return send_from(endpoint.local, endpoint.remote, payload) ? SendResult::sent : SendResult::no_buffer;
}

void Device::receive() {
  DeviceVring& ring = *configuration_.receive;
  bool returned = false;
  while (const auto buffer = ring.take()) {
    returned = true;
    if (buffer->length < header_size || buffer->address == 0) {
      ++dropped_;
      ring.give_back(buffer->head, 0);
      continue;
    }
    const std::uint8_t* bytes = configuration_.buffer_at(buffer->address);
    const std::uint32_t source = get32(bytes);
    const std::uint32_t destination = get32(bytes + 4);
    const std::uint16_t length = get16(bytes + 12);
    Endpoint* target = nullptr;
    for (Endpoint& endpoint : configuration_.endpoints) {
      if (endpoint.local == destination) target = &endpoint;
    }
    if (target == nullptr || header_size + length > buffer->length) {
      ++dropped_;
    } else {
      if (target->remote == 0) target->remote = source;
      target->received(target->context, std::span{bytes + header_size, length});
    }
    ring.give_back(buffer->head, 0);
  }
  // Linux waits for its transmit buffers to come back when it has run out of them.
  if (returned && ring.driver_wants_interrupt()) configuration_.notify(1);
}

}  // namespace duet::rpmsg
