#include "snell/memory/budget.hpp"

#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>

namespace snell::memory {

void Budget::charge(uint64_t bytes, std::string_view consumer) {
  uint64_t used = used_.load(std::memory_order_relaxed);
  for (;;) {
    if (bytes > limit_ || used > limit_ - bytes)
      throw BudgetExceeded(std::string(consumer) + " needs " + format_size(bytes) +
                           ", which would pass the " + format_size(limit_) + " memory limit (" +
                           format_size(used) + " already in use by the scene); raise it with --max-memory");
    if (used_.compare_exchange_weak(used, used + bytes, std::memory_order_relaxed)) break;
  }
  uint64_t peak = peak_.load(std::memory_order_relaxed);
  while (used + bytes > peak && !peak_.compare_exchange_weak(peak, used + bytes, std::memory_order_relaxed)) {
  }
}

void Budget::release(uint64_t bytes) {
  used_.fetch_sub(bytes, std::memory_order_relaxed);
}

Charge::Charge(std::shared_ptr<Budget> budget, uint64_t bytes, std::string_view consumer)
    : budget_(std::move(budget)), consumer_(consumer) {
  if (budget_) budget_->charge(bytes, consumer);
  bytes_ = bytes;
}

Charge::Charge(const Charge& other) : Charge(other.budget_, other.bytes_, other.consumer_) {}

Charge& Charge::operator=(const Charge& other) {
  if (this != &other) *this = Charge(other);
  return *this;
}

Charge::Charge(Charge&& other) noexcept
    : budget_(std::move(other.budget_)), bytes_(other.bytes_), consumer_(std::move(other.consumer_)) {
  other.bytes_ = 0;
}

Charge& Charge::operator=(Charge&& other) noexcept {
  if (this != &other) {
    reset();
    budget_ = std::move(other.budget_);
    bytes_ = other.bytes_;
    consumer_ = std::move(other.consumer_);
    other.bytes_ = 0;
  }
  return *this;
}

Charge::~Charge() {
  reset();
}

void Charge::reset() noexcept {
  if (budget_ && bytes_ > 0) budget_->release(bytes_);
  budget_.reset();
  bytes_ = 0;
}

uint64_t physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return 0;
  return static_cast<uint64_t>(pages) * static_cast<uint64_t>(page_size);
}

uint64_t default_limit() {
  const uint64_t physical = physical_memory_bytes();
  return physical == 0 ? Budget::kUnlimited : physical / 4 * 3;
}

std::optional<uint64_t> parse_size(std::string_view text) {
  size_t digits = 0;
  while (digits < text.size() &&
         (std::isdigit(static_cast<unsigned char>(text[digits])) || text[digits] == '.'))
    ++digits;
  if (digits == 0) return std::nullopt;
  double number = 0;
  try {
    size_t used = 0;
    number = std::stod(std::string(text.substr(0, digits)), &used);
    if (used != digits) return std::nullopt;
  } catch (const std::exception&) {
    return std::nullopt;
  }
  std::string unit;
  for (char c : text.substr(digits)) unit += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  double scale = 1;
  if (!unit.empty() && unit != "b") {
    const size_t power = std::string_view("kmgt").find(unit[0]);
    const std::string rest = unit.substr(1);
    if (power == std::string_view::npos || !(rest.empty() || rest == "b" || rest == "ib"))
      return std::nullopt;
    scale = std::pow(1024.0, static_cast<double>(power + 1));
  }
  const double bytes = std::floor(number * scale);
  if (!(bytes >= 1) || bytes >= 18446744073709551616.0) return std::nullopt;
  return static_cast<uint64_t>(bytes);
}

std::string format_size(uint64_t bytes) {
  static const char* const units[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  if (bytes < 1024) return std::to_string(bytes) + " bytes";
  double value = static_cast<double>(bytes);
  int unit = -1;
  while (value >= 1024 && unit < 5) {
    value /= 1024;
    ++unit;
  }
  char text[32];
  std::snprintf(text, sizeof text, value < 10 ? "%.1f %s" : "%.0f %s", value, units[unit]);
  return text;
}

}  // namespace snell::memory
