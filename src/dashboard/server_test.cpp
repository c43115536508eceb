// The server in-process: files over HTTP, the JSON protocol over WebSocket on the same port.
#include "duet/dashboard/server.hpp"

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/socket.h>

#include <fstream>
#include <thread>

#include "http_client.hpp"

namespace duet::dashboard {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
using tcp = asio::ip::tcp;
using nlohmann::json;

class ServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::filesystem::create_directories(root);
    std::ofstream{root / "index.html"} << "<!doctype html><title>dashboard</title>";
    server = std::make_unique<Server>(
        io, ServerOptions{.web_root = root, .log_name = "test"},
        ServerHandlers{.joined =
                           [](Client& client) {
                             client.send(message({{"type", "description"}}), Delivery::always);
                           },
                       .request =
                           [](Client& client, const json& request) {
                             client.send(message({{"type", "echo"}, {"of", request}}), Delivery::always);
                           }});
    ASSERT_TRUE(server->start().ok());
    thread = std::thread{[this] { io.run(); }};
  }
  void TearDown() override {
    asio::post(io, [this] { io.stop(); });
    thread.join();
    std::filesystem::remove_all(root);
  }

  http::response<http::string_body> get(const std::string& target) {
    return testing::http_request(server->port(), http::verb::get, target);
  }

  std::filesystem::path root = std::filesystem::temp_directory_path() / ("duet-server-" + std::to_string(::getpid()));
  asio::io_context io;
  std::unique_ptr<Server> server;
  std::thread thread;
};

TEST_F(ServerTest, ServesTheFrontEndsFilesAndNothingElse) {
  const auto page = get("/");
  EXPECT_EQ(page.result(), http::status::ok);
  EXPECT_EQ(page[http::field::content_type], "text/html; charset=utf-8");
  EXPECT_EQ(page.body(), "<!doctype html><title>dashboard</title>");
  EXPECT_EQ(get("/../server_test.cpp").result(), http::status::not_found);
  EXPECT_EQ(get("/missing.js").result(), http::status::not_found);
  EXPECT_EQ(server->files_served(), 1U);
}

TEST_F(ServerTest, TalksJsonOverWebSocketOnTheSamePort) {
  asio::io_context client_io;
  beast::websocket::stream<tcp::socket> socket{client_io};
  socket.next_layer().connect({asio::ip::make_address("127.0.0.1"), server->port()});
  const timeval patience{5, 0};
  ::setsockopt(socket.next_layer().native_handle(), SOL_SOCKET, SO_RCVTIMEO, &patience, sizeof(patience));
  socket.handshake("127.0.0.1", "/");
  const auto next = [&socket] {
    beast::flat_buffer buffer;
    socket.read(buffer);
    return json::parse(beast::buffers_to_string(buffer.data()));
  };
  EXPECT_EQ(next()["type"], "description");
  socket.write(asio::buffer(std::string{R"({"type": "status"})"}));
  EXPECT_EQ(next()["of"]["type"], "status");
  socket.write(asio::buffer(std::string{"not json"}));
  const json error = next();
  EXPECT_EQ(error["type"], "error");
  EXPECT_NE(error["message"].get<std::string>().find("type"), std::string::npos);
  EXPECT_EQ(server->clients(), 1U);
}

TEST(ServerWithoutFrontEnd, SaysHowToBuildIt) {
  asio::io_context io;
  Server server{io, ServerOptions{}, ServerHandlers{}};
  ASSERT_TRUE(server.start().ok());
  std::thread thread{[&io] { io.run(); }};
  asio::io_context client_io;
  beast::tcp_stream stream{client_io};
  stream.connect({asio::ip::make_address("127.0.0.1"), server.port()});
  http::request<http::empty_body> request{http::verb::get, "/", 11};
  http::write(stream, request);
  beast::flat_buffer buffer;
  http::response<http::string_body> response;
  http::read(stream, buffer, response);
  EXPECT_NE(response.body().find("npm run build"), std::string::npos);
  asio::post(io, [&io] { io.stop(); });
  thread.join();
}

TEST(ServerAddress, ATakenPortIsAClearFailure) {
  asio::io_context io;
  Server first{io, ServerOptions{}, ServerHandlers{}};
  ASSERT_TRUE(first.start().ok());
  Server second{io, ServerOptions{.port = first.port()}, ServerHandlers{}};
  const Status started = second.start();
  ASSERT_FALSE(started.ok());
  EXPECT_NE(started.error().find("cannot listen on 127.0.0.1:"), std::string::npos);
}

TEST(ServerOwnersRequests, TheOwnerAnswersItsOwnPathsAndARequestPastTheBodyLimitIsRefused) {
  asio::io_context io;
  Server server{io, ServerOptions{.max_upload_size = 100},
                ServerHandlers{.http = [](const HttpRequest& request) -> std::optional<HttpAnswer> {
                  if (request.target != "/echo.bin") return std::nullopt;
                  return HttpAnswer{.status = 200,
                                    .content_type = "application/octet-stream",
                                    .body = request.method + " " + request.body,
                                    .attachment = "echo.bin"};
                }}};
  ASSERT_TRUE(server.start().ok());
  std::thread thread{[&io] { io.run(); }};
  const auto echoed = testing::http_request(server.port(), http::verb::post, "/echo.bin", "hello");
  EXPECT_EQ(echoed.result(), http::status::ok);
  EXPECT_EQ(echoed.body(), "POST hello");
  EXPECT_EQ(echoed[http::field::content_disposition], "attachment; filename=\"echo.bin\"");
  const auto large = testing::http_request(server.port(), http::verb::post, "/echo.bin", std::string(101, 'x'));
  EXPECT_EQ(large.result(), http::status::payload_too_large);
  EXPECT_NE(large.body().find("larger than 100 bytes"), std::string::npos);
  // Paths the owner does not answer are the front end's files, which take no POST.
  EXPECT_EQ(testing::http_request(server.port(), http::verb::post, "/other", "x").result(),
            http::status::method_not_allowed);
  asio::post(io, [&io] { io.stop(); });
  thread.join();
}

}  // namespace
}  // namespace duet::dashboard
