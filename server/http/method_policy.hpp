#pragma once
// A known path asked with a method it does not serve: 405 with an Allow header listing the methods
// its routes register (HEAD wherever GET is, as httplib answers HEAD with the GET handler).
#include <httplib.h>

#include "server/http/router.hpp"

namespace lp::server {

// For a request no route took (httplib answers 404, or 400 for methods it does not route such as
// TRACE): writes the 405 and returns true if `router` serves its path, but not with its method;
// false (response untouched) otherwise.
bool refuse_method(const Router& router, const httplib::Request& req, httplib::Response& res);

}  // namespace lp::server
