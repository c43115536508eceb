#include "relay.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <signal.h>
#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <sys/signalfd.h>
#include <sys/socket.h>
#include <sys/timerfd.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <iostream>
#include <sstream>

#include "duet/xcp/protocol.hpp"

namespace duet::bridge {
namespace {

constexpr std::size_t max_packet = 0xFFFF;
constexpr std::chrono::milliseconds longest_retry{2000};
constexpr std::uint8_t disconnect_command = static_cast<std::uint8_t>(xcp::Command::disconnect);
// A master on UDP has no connection to lose: one silent this long is taken to be gone.
constexpr std::chrono::seconds udp_master_silence{30};

bool same_peer(const sockaddr_in& a, const sockaddr_in& b) {
  return a.sin_addr.s_addr == b.sin_addr.s_addr && a.sin_port == b.sin_port;
}

std::string peer_name(const sockaddr_in& peer) {
  char text[INET_ADDRSTRLEN] = {};
  inet_ntop(AF_INET, &peer.sin_addr, text, sizeof(text));
  return std::string{text} + ":" + std::to_string(ntohs(peer.sin_port));
}

// The LEN/CTR header of a frame that carries `size` bytes.
std::array<std::uint8_t, 4> frame_header(std::uint16_t counter, std::size_t size) {
  return {static_cast<std::uint8_t>(size), static_cast<std::uint8_t>(size >> 8U), static_cast<std::uint8_t>(counter),
          static_cast<std::uint8_t>(counter >> 8U)};
}

}  // namespace

Relay::Relay(RelayOptions options)
    : options_(std::move(options)),
      channel_buffer_(xcp::ethernet_framing.frame_size(max_packet)),
      master_buffer_(xcp::ethernet_framing.frame_size(max_packet)),
      from_channel_(xcp::ethernet_framing, channel_buffer_, max_packet),
      from_master_(xcp::ethernet_framing, master_buffer_, max_packet),
      session_(options_.owed_answer_patience) {}

Relay::~Relay() {
  for (int descriptor : {epoll_, listener_, udp_, wake_, retry_timer_, channel_, master_}) {
    if (descriptor >= 0) ::close(descriptor);
  }
}

void Relay::log(const std::string& line) const { std::cerr << "duet-bridge: " << line << std::endl; }

Status Relay::start() {
  epoll_ = epoll_create1(EPOLL_CLOEXEC);
  wake_ = eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
  retry_timer_ = timerfd_create(CLOCK_MONOTONIC, TFD_CLOEXEC | TFD_NONBLOCK);
  listener_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  const int on = 1;
  setsockopt(listener_, SOL_SOCKET, SO_REUSEADDR, &on, sizeof(on));
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(options_.listen_port);
  if (inet_pton(AF_INET, options_.listen_address.c_str(), &address.sin_addr) != 1) {
    return Failure{"'" + options_.listen_address + "' is not an IPv4 address to listen on"};
  }
  if (::bind(listener_, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0 || ::listen(listener_, 4) != 0) {
    return Failure{options_.listen_address + ":" + std::to_string(options_.listen_port) + ": " + std::strerror(errno)};
  }
  socklen_t length = sizeof(address);
  getsockname(listener_, reinterpret_cast<sockaddr*>(&address), &length);
  port_ = ntohs(address.sin_port);
  udp_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);  // XCP on UDP, on the same port
  if (::bind(udp_, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0) {
    return Failure{options_.listen_address + ":" + std::to_string(port_) + " (UDP): " + std::strerror(errno)};
  }
  for (int descriptor : {listener_, udp_, wake_, retry_timer_}) {
    epoll_event event{EPOLLIN, {.fd = descriptor}};
    epoll_ctl(epoll_, EPOLL_CTL_ADD, descriptor, &event);
  }
  log("listening for an XCP master on " + options_.listen_address + ":" + std::to_string(port_) + " (TCP and UDP)");
  open_channel_now();
  return done();
}

void Relay::arm_retry(std::chrono::milliseconds delay) {
  itimerspec timer{};
  timer.it_value.tv_sec = static_cast<time_t>(delay.count() / 1000);
  timer.it_value.tv_nsec = static_cast<long>((delay.count() % 1000) * 1'000'000);
  timerfd_settime(retry_timer_, 0, &timer, nullptr);
}

void Relay::open_channel_now() {
  if (channel_ >= 0) return;
  Result<int> opened = open_channel(options_.channel);
  if (!opened) {
    if (retry_delay_ == std::chrono::milliseconds{100} || options_.verbose) log(opened.error() + "; retrying");
    arm_retry(retry_delay_);
    retry_delay_ = std::min(retry_delay_ * 2, longest_retry);
    return;
  }
  channel_ = opened.value();
  retry_delay_ = std::chrono::milliseconds{100};
  ++channel_opens_;
  channel_open_ = true;
  epoll_event event{EPOLLIN, {.fd = channel_}};
  epoll_ctl(epoll_, EPOLL_CTL_ADD, channel_, &event);
  channel_watched_for_output_ = false;
  log("channel " + options_.channel_uri + " open");
}

void Relay::close_channel(const std::string& reason) {
  if (channel_ < 0) return;
  epoll_ctl(epoll_, EPOLL_CTL_DEL, channel_, nullptr);
  ::close(channel_);
  channel_ = -1;
  channel_open_ = false;
  discard_partial_frame(from_channel_);
  slave_next_counter_.reset();
  to_channel_.clear();
  session_.channel_reset();  // what the commands written or waiting still wait for will not come: counted there
  log("channel " + options_.channel_uri + " closed (" + reason + "); retrying");
  arm_retry(retry_delay_);
  // Commands held back will not reach this slave either: the master hears so now, not after a timeout.
  std::deque<HeldCommand> held = std::move(held_commands_);
  held_commands_.clear();
  held_bytes_ = 0;
  for (const HeldCommand& command : held) refuse_command(command.packet);
}

void Relay::accept_master() {
  sockaddr_in peer{};
  socklen_t length = sizeof(peer);
  const int accepted = ::accept4(listener_, reinterpret_cast<sockaddr*>(&peer), &length, SOCK_CLOEXEC | SOCK_NONBLOCK);
  if (accepted < 0) return;
  const std::string who = peer_name(peer);
  // The master may have closed in the same instant (a master reconnecting at once): take its end of file first, so
  // that its successor is not refused.
  if (master_ >= 0) read_master();
  if (has_master()) {  // XCP has one master
    ::close(accepted);
    ++masters_refused_;
    log("refused a second master from " + who + ": one master at a time");
    return;
  }
  master_ = accepted;
  const int on = 1;
  setsockopt(master_, IPPROTO_TCP, TCP_NODELAY, &on, sizeof(on));
  if (options_.master_send_buffer > 0) {
    setsockopt(master_, SOL_SOCKET, SO_SNDBUF, &options_.master_send_buffer, sizeof(options_.master_send_buffer));
  }
  next_counter_to_master_ = 0;
  ++masters_served_;
  master_connected_ = true;
  epoll_event event{EPOLLIN, {.fd = master_}};
  epoll_ctl(epoll_, EPOLL_CTL_ADD, master_, &event);
  master_watched_for_output_ = false;
  if (options_.verbose) log("master " + who + " connected");
}

void Relay::close_master(const std::string& reason) {
  if (master_ < 0) return;
  epoll_ctl(epoll_, EPOLL_CTL_DEL, master_, nullptr);
  ::close(master_);
  master_ = -1;
  to_master_.clear();
  discard_partial_frame(from_master_);
  master_gone(reason);
}

void Relay::forget_udp_master(const std::string& reason) {
  if (!udp_master_) return;
  udp_master_.reset();
  udp_master_leaving_ = false;
  master_gone(reason);
}

// The master went away: end its session with the slave, if one is open, so that DAQ stops. The answers still to come
// are owed to nobody (SessionTracker).
void Relay::master_gone(const std::string& reason) {
  master_connected_ = false;
  if (options_.verbose) log("master gone (" + reason + ")");
  commands_abandoned_ += held_commands_.size();  // held back, never sent, and nobody waits for them now
  held_commands_.clear();
  held_bytes_ = 0;
  const auto now = std::chrono::steady_clock::now();
  if (session_.master_gone(now) && channel_ >= 0) {
    const std::array<std::uint8_t, 1> disconnect{disconnect_command};
    enqueue_to_slave(0, disconnect);
    session_.relay_disconnect(now);
  }
}

void Relay::enqueue_to_slave(std::uint16_t counter, std::span<const std::uint8_t> packet) {
  to_channel_.append(frame_header(counter, packet.size()));
  to_channel_.append(packet);
  ++frames_to_slave_;
}

void Relay::discard_partial_frame(xcp::FrameDecoder& decoder) {
  partial_frame_bytes_ += decoder.buffered();
  decoder.reset();
}

void Relay::read_channel() {
  std::vector<std::uint8_t>& buffer = read_buffer_;
  for (;;) {
    const ssize_t received = ::read(channel_, buffer.data(), buffer.size());
    if (received < 0 && (errno == EAGAIN || errno == EINTR)) return;
    if (received <= 0) {
      close_channel(received == 0 ? "end of file" : std::strerror(errno));
      return;
    }
    from_channel_.feed(
        std::span{buffer}.first(static_cast<std::size_t>(received)),
        [this](std::uint16_t counter, std::span<const std::uint8_t> packet) { forward_to_master(counter, packet); });
    channel_stalled_since_ = std::chrono::steady_clock::now();
    if (static_cast<std::size_t>(received) < buffer.size()) return;  // drained; epoll (level-triggered) says if not
  }
}

void Relay::read_master() {
  std::vector<std::uint8_t>& buffer = read_buffer_;
  for (;;) {
    const ssize_t received = ::recv(master_, buffer.data(), buffer.size(), 0);
    if (received < 0 && (errno == EAGAIN || errno == EINTR)) return;
    if (received <= 0) {
      close_master(received == 0 ? "closed" : std::strerror(errno));
      return;
    }
    from_master_.feed(
        std::span{buffer}.first(static_cast<std::size_t>(received)),
        [this](std::uint16_t counter, std::span<const std::uint8_t> packet) { forward_to_slave(counter, packet); });
    master_stalled_since_ = std::chrono::steady_clock::now();
    if (static_cast<std::size_t>(received) < buffer.size()) return;
  }
}

void Relay::forward_to_master(std::uint16_t counter, std::span<const std::uint8_t> packet) {
  slave_next_counter_ = static_cast<std::uint16_t>(counter + 1U);
  const SessionTracker::Delivery delivery = session_.slave_packet(packet, std::chrono::steady_clock::now());
  if (!delivery.to_master || !has_master()) {
    ++frames_without_master_;
    release_held_commands();  // the answer they waited behind may have been this one
    return;
  }
  deliver_to_master(counter, packet);
  if (udp_master_leaving_ && delivery.answers_command == disconnect_command) forget_udp_master("disconnected");
}

void Relay::deliver_to_master(std::uint16_t counter, std::span<const std::uint8_t> packet) {
  next_counter_to_master_ = static_cast<std::uint16_t>(counter + 1U);
  const bool daq = packet[0] < xcp::pid::service;
  if (udp_master_) {
    send_to_udp_master(counter, packet, daq);
    return;
  }
  if (daq && to_master_.size() > options_.master_queue_limit) {
    ++daq_frames_dropped_;  // the master does not keep up: drop DAQ, never answers
    return;
  }
  to_master_.append(frame_header(counter, packet.size()));
  to_master_.append(packet);
  ++frames_to_master_;
}

// One frame per datagram; a datagram the kernel will not take now is lost, as UDP may lose it anyway (counted).
void Relay::send_to_udp_master(std::uint16_t counter, std::span<const std::uint8_t> packet, bool daq) {
  std::atomic<std::uint64_t>& lost = daq ? daq_frames_dropped_ : answers_dropped_;
  if (packet.size() > max_datagram_packet) {
    ++lost;
    return;
  }
  const auto header = frame_header(counter, packet.size());
  std::array<std::uint8_t, 4 + max_datagram_packet> datagram{};
  std::memcpy(datagram.data(), header.data(), header.size());
  std::memcpy(datagram.data() + header.size(), packet.data(), packet.size());
  const ssize_t sent = ::sendto(udp_, datagram.data(), header.size() + packet.size(), MSG_DONTWAIT,
                                reinterpret_cast<const sockaddr*>(&*udp_master_), sizeof(sockaddr_in));
  if (sent <= 0) {
    ++lost;
    return;
  }
  bytes_to_master_ += static_cast<std::uint64_t>(sent);
  ++frames_to_master_;
}

void Relay::read_udp() {
  for (;;) {
    sockaddr_in peer{};
    socklen_t length = sizeof(peer);
    const ssize_t received = ::recvfrom(udp_, read_buffer_.data(), read_buffer_.size(), MSG_DONTWAIT,
                                        reinterpret_cast<sockaddr*>(&peer), &length);
    if (received < 0) return;  // EAGAIN, or an ICMP error for an earlier datagram: nothing to read now
    if (master_ >= 0 || (udp_master_ && !same_peer(*udp_master_, peer))) {  // XCP has one master
      ++masters_refused_;
      if (!last_refused_ || !same_peer(*last_refused_, peer)) {
        log("refused a second master from " + peer_name(peer) + " (UDP): one master at a time");
      }
      last_refused_ = peer;
      continue;
    }
    if (!udp_master_) {
      udp_master_ = peer;
      next_counter_to_master_ = 0;
      ++masters_served_;
      master_connected_ = true;
      if (options_.verbose) log("master " + peer_name(peer) + " (UDP) connected");
    }
    udp_master_heard_ = std::chrono::steady_clock::now();
    from_master_.feed(
        std::span{read_buffer_}.first(static_cast<std::size_t>(received)),
        [this](std::uint16_t counter, std::span<const std::uint8_t> frame) { forward_to_slave(counter, frame); });
    discard_partial_frame(from_master_);  // a datagram holds whole frames: nothing carries over to the next
  }
}

// A command from the master: to the slave, held back while answers are owed to nobody, or refused.
void Relay::forward_to_slave(std::uint16_t counter, std::span<const std::uint8_t> packet) {
  const std::size_t frame_size = xcp::ethernet_framing.frame_size(packet.size());
  if (channel_ < 0 || to_channel_.size() + held_bytes_ + frame_size > options_.slave_queue_limit) {
    refuse_command(packet);
    return;
  }
  if (session_.owes_answers()) {
    held_commands_.push_back({counter, {packet.begin(), packet.end()}});
    held_bytes_ += frame_size;
    return;
  }
  send_command(counter, packet);
}

void Relay::send_command(std::uint16_t counter, std::span<const std::uint8_t> packet) {
  const bool answered = session_.master_command(packet, std::chrono::steady_clock::now());
  enqueue_to_slave(counter, packet);
  if (packet[0] == disconnect_command && udp_master_) {
    udp_master_leaving_ = answered;                    // then forgotten once the answer has gone back
    if (!answered) forget_udp_master("disconnected");  // a disconnected slave will not answer
  }
}

// ERR_CMD_BUSY tells a master to try the command again (XCP's pre-action for it), rather than wait for a timeout.
void Relay::refuse_command(std::span<const std::uint8_t> packet) {
  ++commands_refused_;
  const std::array<std::uint8_t, 2> busy{xcp::pid::error, static_cast<std::uint8_t>(xcp::Error::cmd_busy)};
  if (has_master()) deliver_to_master(next_counter_to_master_, busy);
  if (packet[0] == disconnect_command && udp_master_) forget_udp_master("disconnected");
}

void Relay::release_held_commands() {
  while (!held_commands_.empty() && !session_.owes_answers()) {
    const HeldCommand command = std::move(held_commands_.front());
    held_commands_.pop_front();
    held_bytes_ -= xcp::ethernet_framing.frame_size(command.packet.size());
    send_command(command.counter, command.packet);
  }
}

void Relay::flush_stale_frames() {
  const std::chrono::milliseconds gap = options_.quiet_gap;
  const auto now = std::chrono::steady_clock::now();
  const bool slave_frame_on_its_way = slave_next_counter_ && from_channel_.holds_start_of_frame(*slave_next_counter_);
  if (channel_ >= 0 && from_channel_.buffered() > 0 && now - channel_stalled_since_ >= gap && !slave_frame_on_its_way) {
    from_channel_.flush_stale(
        [this](std::uint16_t counter, std::span<const std::uint8_t> packet) { forward_to_master(counter, packet); });
  }
  if (master_ >= 0 && from_master_.buffered() > 0 && now - master_stalled_since_ >= gap) {
    from_master_.flush_stale(
        [this](std::uint16_t counter, std::span<const std::uint8_t> packet) { forward_to_slave(counter, packet); });
  }
}

void Relay::flush_master() {
  while (master_ >= 0 && !to_master_.empty()) {
    const std::span<const std::uint8_t> bytes = to_master_.front();
    const ssize_t sent = ::send(master_, bytes.data(), bytes.size(), MSG_NOSIGNAL);
    if (sent < 0 && (errno == EAGAIN || errno == EINTR)) return;
    if (sent <= 0) {
      close_master(std::strerror(errno));
      return;
    }
    bytes_to_master_ += static_cast<std::uint64_t>(sent);
    to_master_.consume(static_cast<std::size_t>(sent));
  }
}

// At most one RPMsg payload per write; EAGAIN waits for the channel, ENOMEM (no free RPMsg buffer) backs off.
void Relay::flush_channel() {
  while (channel_ >= 0 && !to_channel_.empty()) {
    const std::span<const std::uint8_t> bytes = to_channel_.front();
    const std::size_t chunk = std::min(bytes.size(), options_.channel_chunk);
    const ssize_t written = ::write(channel_, bytes.data(), chunk);
    if (written < 0 && (errno == EAGAIN || errno == EINTR)) return;
    if (written < 0 && errno == ENOMEM) {
      arm_retry(std::chrono::milliseconds{1});
      return;
    }
    if (written <= 0) {
      close_channel(std::strerror(errno));
      return;
    }
    bytes_to_slave_ += static_cast<std::uint64_t>(written);
    to_channel_.consume(static_cast<std::size_t>(written));
  }
}

// Asks for EPOLLOUT only while bytes wait, and tells epoll only when that changes: a system call saved per message.
void Relay::update_interest() {
  const auto watch = [this](int descriptor, bool waiting, bool& watching_output) {
    if (descriptor < 0 || waiting == watching_output) return;
    epoll_event event{EPOLLIN | (waiting ? static_cast<std::uint32_t>(EPOLLOUT) : 0U), {.fd = descriptor}};
    epoll_ctl(epoll_, EPOLL_CTL_MOD, descriptor, &event);
    watching_output = waiting;
  };
  watch(master_, !to_master_.empty(), master_watched_for_output_);
  watch(channel_, !to_channel_.empty(), channel_watched_for_output_);
}

void Relay::run(bool handle_signals, const std::function<std::string()>& more_status) {
  int signals = -1;
  if (handle_signals) {
    sigset_t set;
    sigemptyset(&set);
    for (int number : {SIGINT, SIGTERM, SIGUSR1}) sigaddset(&set, number);
    sigprocmask(SIG_BLOCK, &set, nullptr);
    signals = signalfd(-1, &set, SFD_CLOEXEC | SFD_NONBLOCK);
    epoll_event event{EPOLLIN, {.fd = signals}};
    epoll_ctl(epoll_, EPOLL_CTL_ADD, signals, &event);
  }
  running_ = true;
  std::array<epoll_event, 8> events{};
  while (running_) {
    // Without a partial frame waiting, sleep until something happens; with one, wake up to give up on it.
    const bool waiting =
        (channel_ >= 0 && from_channel_.buffered() > 0) || (master_ >= 0 && from_master_.buffered() > 0);
    int timeout = waiting ? static_cast<int>(options_.quiet_gap.count()) + 5 : udp_master_ ? 1000 : -1;
    if (const auto owed_until = session_.owed_until()) {  // and to give up answers that do not come
      const auto left =
          std::chrono::ceil<std::chrono::milliseconds>(*owed_until - std::chrono::steady_clock::now()).count();
      const int until_given_up = static_cast<int>(std::max<decltype(left)>(left, 0));
      timeout = timeout < 0 ? until_given_up : std::min(timeout, until_given_up);
    }
    const int ready = epoll_wait(epoll_, events.data(), static_cast<int>(events.size()), timeout);
    if (ready < 0 && errno != EINTR) break;
    for (int index = 0; index < ready; ++index) {
      const int descriptor = events[static_cast<std::size_t>(index)].data.fd;
      const std::uint32_t what = events[static_cast<std::size_t>(index)].events;
      if (descriptor == wake_) {
        std::uint64_t ignored = 0;
        [[maybe_unused]] const ssize_t read = ::read(wake_, &ignored, sizeof(ignored));
      } else if (descriptor == signals) {
        signalfd_siginfo info{};
        while (::read(signals, &info, sizeof(info)) == sizeof(info)) {
          if (info.ssi_signo == SIGUSR1) {
            log(status());
            if (more_status) log(more_status());
          } else {
            running_ = false;
          }
        }
      } else if (descriptor == retry_timer_) {
        std::uint64_t expirations = 0;
        [[maybe_unused]] const ssize_t read = ::read(retry_timer_, &expirations, sizeof(expirations));
        if (channel_ < 0) open_channel_now();
      } else if (descriptor == listener_) {
        accept_master();
      } else if (descriptor == udp_) {
        read_udp();
      } else if (descriptor == channel_ && channel_ >= 0) {
        if ((what & (EPOLLIN | EPOLLHUP | EPOLLERR)) != 0) read_channel();
      } else if (descriptor == master_ && master_ >= 0) {
        if ((what & (EPOLLIN | EPOLLHUP | EPOLLERR)) != 0) read_master();
      }
    }
    if (udp_master_ && std::chrono::steady_clock::now() - udp_master_heard_ > udp_master_silence) {
      forget_udp_master("silent for " + std::to_string(udp_master_silence.count()) + " s");
    }
    if (session_.give_up_owed_answers(std::chrono::steady_clock::now())) release_held_commands();
    flush_stale_frames();
    flush_channel();
    flush_master();
    update_interest();
  }
  if (signals >= 0) ::close(signals);
}

void Relay::stop() {
  running_ = false;
  const std::uint64_t one = 1;
  [[maybe_unused]] const ssize_t written = ::write(wake_, &one, sizeof(one));
}

RelayCounters Relay::counters() const {
  RelayCounters counters;
  counters.frames_to_master = frames_to_master_;
  counters.frames_to_slave = frames_to_slave_;
  counters.bytes_to_master = bytes_to_master_;
  counters.bytes_to_slave = bytes_to_slave_;
  counters.daq_frames_dropped = daq_frames_dropped_;
  counters.answers_dropped = answers_dropped_;
  counters.frames_without_master = frames_without_master_;
  counters.commands_refused = commands_refused_;
  const SessionTracker::Figures figures = session_.figures();
  counters.commands_unanswered = figures.commands_unanswered + commands_abandoned_;
  counters.garbage_bytes = from_channel_.dropped_bytes() + from_master_.dropped_bytes() + partial_frame_bytes_;
  counters.channel_opens = channel_opens_;
  counters.masters_served = masters_served_;
  counters.masters_refused = masters_refused_;
  counters.responses = figures.responses;
  counters.latency_mean_us =
      figures.responses == 0 ? 0 : figures.latency_total_us / static_cast<double>(figures.responses);
  counters.latency_max_us = figures.latency_max_us;
  return counters;
}

std::string Relay::status() const {
  const RelayCounters counters = this->counters();
  std::ostringstream out;
  out << "channel " << (channel_open_ ? "open" : "closed") << ", master " << (master_connected_ ? "connected" : "none")
      << "; frames to master " << counters.frames_to_master << " (" << counters.bytes_to_master << " bytes), to slave "
      << counters.frames_to_slave << " (" << counters.bytes_to_slave << " bytes); DAQ frames dropped "
      << counters.daq_frames_dropped << "; answers dropped " << counters.answers_dropped << "; frames without master "
      << counters.frames_without_master << "; commands refused " << counters.commands_refused << ", unanswered "
      << counters.commands_unanswered << "; garbage bytes " << counters.garbage_bytes << "; channel opened "
      << counters.channel_opens << " times; masters served " << counters.masters_served << ", refused "
      << counters.masters_refused << "; responses " << counters.responses << ", latency mean "
      << counters.latency_mean_us << " us, max " << counters.latency_max_us << " us";
  return out.str();
}

}  // namespace duet::bridge
