#pragma once
// For tests: one HTTP request to a dashboard back end on 127.0.0.1, answered synchronously.

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include <cstdint>
#include <string>

namespace duet::dashboard::testing {

inline boost::beast::http::response<boost::beast::http::string_body> http_request(
    std::uint16_t port, boost::beast::http::verb method, const std::string& target, std::string body = {},
    const std::string& content_type = "application/json") {
  namespace http = boost::beast::http;
  boost::asio::io_context io;
  boost::beast::tcp_stream stream{io};
  stream.connect({boost::asio::ip::make_address("127.0.0.1"), port});
  http::request<http::string_body> request{method, target, 11};
  request.set(http::field::host, "127.0.0.1");
  if (!body.empty()) request.set(http::field::content_type, content_type);
  request.body() = std::move(body);
  request.prepare_payload();
  http::write(stream, request);
  boost::beast::flat_buffer buffer;
  http::response_parser<http::string_body> parser;
  parser.body_limit(std::uint64_t{256} << 20);  // the files the tests download
  http::read(stream, buffer, parser);
  return parser.release();
}

}  // namespace duet::dashboard::testing
