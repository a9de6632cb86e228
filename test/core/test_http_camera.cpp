/**
 * \file
 * \brief The HTTP link against the emulated cameras' server on 127.0.0.1: Digest with the nonce reused and one
 * connection kept, stale nonces, Basic, a wrong password, deadlines, a camera that is not there.
 */
#include <gtest/gtest.h>

#include <future>
#include <mutex>

#include <boost/asio/post.hpp>

#include "ptz_action_server/core/transport/http_link.h"
#include "ptz_action_server/emulators/http_camera_server.h"
#include "wait_until.h"

namespace ptz_action_server
{
namespace
{
/// An HTTP link on its own I/O thread, as a session runs it.
class HttpHarness : private Link::Listener
{
public:
  explicit HttpHarness(const LinkConfig& config) : link_(Link::create(context_, config, *this))
  {
    thread_ = std::thread([this] {
      auto work = boost::asio::make_work_guard(context_);
      context_.run();
    });
    boost::asio::post(context_, [this] { link_->open(); });
    EXPECT_TRUE(waitUntil([this] { return up(); }, 10.0));
  }
  ~HttpHarness() override
  {
    boost::asio::post(context_, [this] {
      link_->close();
      context_.stop();
    });
    thread_.join();
  }

  HttpReply perform(const std::string& path, const std::string& body = "")
  {
    std::promise<HttpReply> done;
    boost::asio::post(context_, [&] {
      HttpRequest request{ path, body, body.empty() ? "" : "application/soap+xml; charset=utf-8" };
      done.set_value(link_->http()->request(request));
    });
    return done.get_future().get();
  }
  bool up() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return up_;
  }
  std::vector<std::string> losses() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return losses_;
  }
  Link& link()
  {
    return *link_;
  }
  const HttpCounters& counters() const
  {
    return link_->http()->httpCounters();
  }

private:
  void onLinkUp() override
  {
    std::lock_guard<std::mutex> lock(mutex_);
    up_ = true;
  }
  void onLinkBytes(const std::uint8_t*, std::size_t) override
  {
  }
  void onLinkDown(const std::string& reason) override
  {
    std::lock_guard<std::mutex> lock(mutex_);
    up_ = false;
    losses_.push_back(reason);
  }

  boost::asio::io_context context_;
  std::unique_ptr<Link> link_;
  std::thread thread_;
  mutable std::mutex mutex_;
  bool up_ = false;
  std::vector<std::string> losses_;
};

HttpCameraServer::Handler answerOk()
{
  return [](const std::string&, const std::string& target, const std::string& body) {
    return HttpAnswer{ 200, "text/plain", "ok " + target + " " + body };
  };
}

LinkConfig linkTo(const HttpCameraServer& server, HttpAuth auth, const std::string& password = "pass")
{
  LinkConfig link;
  link.kind = LinkKind::HTTP;
  link.port = server.port();
  link.http.auth = auth;
  link.http.username = "root";
  link.http.password = password;
  link.http.request_timeout = 2.0;
  return link;
}

TEST(HttpLink, DigestCostsOneChallengeAndOneConnectionForAHundredRequests)
{
  HttpCameraServer server(HttpCameraServerConfig(), answerOk());
  HttpHarness client(linkTo(server, HttpAuth::DIGEST));
  for (int index = 0; index < 100; ++index)
  {
    const HttpReply reply = client.perform("/axis-cgi/com/ptz.cgi?query=position&n=" + std::to_string(index));
    ASSERT_TRUE(reply.delivered);
    ASSERT_EQ(reply.status, 200);
    EXPECT_EQ(reply.body, "ok /axis-cgi/com/ptz.cgi?query=position&n=" + std::to_string(index) + " ");
  }
  EXPECT_EQ(server.counters().connections, 1u);
  EXPECT_EQ(server.counters().challenges, 1u);  // the nonce is reused: one round trip per request after the first
  EXPECT_EQ(server.counters().requests, 101u);
  EXPECT_EQ(client.counters().connections, 1u);
  EXPECT_EQ(client.counters().requests, 100u);
}

TEST(HttpLink, AStaleNonceIsRenegotiatedWithinTheRequest)
{
  HttpCameraServerConfig config;
  config.nonce_uses = 10;
  HttpCameraServer server(config, answerOk());
  HttpHarness client(linkTo(server, HttpAuth::DIGEST));
  for (int index = 0; index < 50; ++index)
  {
    const HttpReply reply = client.perform("/x?n=" + std::to_string(index), "<a/>");  // POSTs, as ONVIF sends
    ASSERT_TRUE(reply.delivered);
    ASSERT_EQ(reply.status, 200) << index;
  }
  EXPECT_EQ(server.counters().connections, 1u);
  EXPECT_EQ(server.counters().refused_credentials, 0u);
  EXPECT_LE(server.counters().challenges, 7u);  // the first POST and curl's probe, then one per stale nonce
}

TEST(HttpLink, BasicAndAutomaticAuthentication)
{
  HttpCameraServerConfig basic_config;
  basic_config.auth = HttpAuth::BASIC;
  HttpCameraServer basic(basic_config, answerOk());
  HttpHarness basic_client(linkTo(basic, HttpAuth::BASIC));
  for (int index = 0; index < 20; ++index)
  {
    ASSERT_EQ(basic_client.perform("/b").status, 200);
  }
  EXPECT_EQ(basic.counters().challenges, 0u);  // Basic goes with the first request

  HttpCameraServer digest(HttpCameraServerConfig(), answerOk());
  HttpHarness auto_client(linkTo(digest, HttpAuth::AUTO));
  for (int index = 0; index < 20; ++index)
  {
    ASSERT_EQ(auto_client.perform("/d").status, 200);
  }
  EXPECT_LE(digest.counters().challenges, 2u);  // once learnt, only Digest: the nonce is reused
  EXPECT_EQ(digest.counters().connections, 1u);
}

TEST(HttpLink, AWrongPasswordIsAnAnswerNotALoss)
{
  HttpCameraServer server(HttpCameraServerConfig(), answerOk());
  HttpHarness client(linkTo(server, HttpAuth::DIGEST, "wrong"));
  const HttpReply reply = client.perform("/axis-cgi/com/ptz.cgi?query=limits");
  EXPECT_TRUE(reply.delivered);
  EXPECT_EQ(reply.status, 401);
  EXPECT_GE(server.counters().refused_credentials, 1u);
  EXPECT_TRUE(client.losses().empty());
}

TEST(HttpLink, ASilentCameraMeetsTheDeadlineAndTheLinkIsLostWithTheReason)
{
  HttpCameraServer server(HttpCameraServerConfig(), answerOk());
  LinkConfig config = linkTo(server, HttpAuth::DIGEST);
  config.http.request_timeout = 0.3;
  HttpHarness client(config);
  ASSERT_EQ(client.perform("/first").status, 200);
  server.setSilent(true);
  const HttpReply reply = client.perform("/second");
  EXPECT_FALSE(reply.delivered);
  ASSERT_EQ(client.losses().size(), 1u);
  EXPECT_EQ(client.losses()[0],
            "http://127.0.0.1:" + std::to_string(server.port()) + ": GET /second: no answer within 0.30 s");
  EXPECT_EQ(client.counters().timeouts, 1u);
  server.setSilent(false);
  ASSERT_TRUE(waitUntil([&] { return client.up(); }, 10.0)) << "reopened after the backoff";
  EXPECT_EQ(client.perform("/third").status, 200);
}

TEST(HttpLink, ACameraThatIsNotThereIsNamed)
{
  std::uint16_t port = 0;
  {
    HttpCameraServer server(HttpCameraServerConfig(), answerOk());
    port = server.port();
  }
  LinkConfig config;
  config.kind = LinkKind::HTTP;
  config.port = port;
  HttpHarness client(config);
  const HttpReply reply = client.perform("/axis-cgi/com/ptz.cgi?query=limits");
  EXPECT_FALSE(reply.delivered);
  ASSERT_EQ(client.losses().size(), 1u);
  EXPECT_EQ(client.losses()[0].rfind(
                "http://127.0.0.1:" + std::to_string(port) + ": GET /axis-cgi/com/ptz.cgi?query=limits: ", 0),
            0u)
      << client.losses()[0];
  EXPECT_EQ(client.counters().transport_errors, 1u);
  EXPECT_FALSE(client.link().refusedForGood()) << "a camera that is away may come back";
}

/// Listens to nothing: a link that is never opened.
class Deaf : public Link::Listener
{
  void onLinkUp() override
  {
  }
  void onLinkBytes(const std::uint8_t*, std::size_t) override
  {
  }
  void onLinkDown(const std::string&) override
  {
  }
};

TEST(HttpLink, CarriesRequestsNotBytesAndAUdpLinkTheOpposite)
{
  boost::asio::io_context context;
  Deaf deaf;
  LinkConfig http;
  http.kind = LinkKind::HTTP;
  http.port = 80;
  const std::unique_ptr<Link> http_link = Link::create(context, http, deaf);
  EXPECT_EQ(http_link->bytes(), nullptr);
  EXPECT_NE(http_link->http(), nullptr);
  LinkConfig udp;
  udp.kind = LinkKind::UDP;
  udp.port = 9;
  const std::unique_ptr<Link> udp_link = Link::create(context, udp, deaf);
  EXPECT_NE(udp_link->bytes(), nullptr);
  EXPECT_EQ(udp_link->http(), nullptr);
  EXPECT_FALSE(udp_link->refusedForGood());
}

}  // namespace
}  // namespace ptz_action_server
