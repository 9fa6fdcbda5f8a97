#include "sbsim/services/ServiceRegistry.h"

#include <stdexcept>
#include <utility>

#include "sbsim/services/Service.h"
#include "sbsim/services/ServicesConfig.h"

namespace sbsim::services {

ServiceRegistry& ServiceRegistry::instance() {
    static ServiceRegistry registry;
    return registry;
}

void ServiceRegistry::add(const std::string& name, Factory factory) { add(name, std::move(factory), {}); }

void ServiceRegistry::add(const std::string& name, Factory factory, ServiceTraits traits) {
    if (!factories_.emplace(name, Entry{std::move(factory), traits}).second && !conflict_) conflict_ = name;
}

ServiceTraits ServiceRegistry::traits(const std::string& name) const {
    const auto it = factories_.find(name);
    return it == factories_.end() ? ServiceTraits{} : it->second.traits;
}

ServiceTraits ServiceRegistry::traits(const ServiceSpec& spec) const {
    const Resolver* resolver = resolverOf(spec.type);
    if (resolver == nullptr) return traits(spec.type);
    return resolver->traits ? resolver->traits(spec) : ServiceTraits{};
}

std::vector<std::filesystem::path> ServiceRegistry::files(const ServiceSpec& spec) const {
    const Resolver* resolver = resolverOf(spec.type);
    if (resolver == nullptr || !resolver->files) return {};
    return resolver->files(spec);
}

std::optional<std::string> ServiceRegistry::takeConflict() { return std::exchange(conflict_, std::nullopt); }

void ServiceRegistry::addResolver(const std::string& prefix, Resolver resolver) {
    if (!resolvers_.emplace(prefix, std::move(resolver)).second && !conflict_) conflict_ = prefix;
}

const ServiceRegistry::Resolver* ServiceRegistry::resolverOf(const std::string& type) const {
    for (const auto& [prefix, resolver] : resolvers_) {
        if (type.compare(0, prefix.size(), prefix) == 0) return &resolver;
    }
    return nullptr;
}

std::unique_ptr<Service> ServiceRegistry::create(const ServiceSpec& spec) const {
    if (const Resolver* resolver = resolverOf(spec.type)) return resolver->create(spec);
    return create(spec.type);
}

void ServiceRegistry::check(const ServiceSpec& spec) const {
    if (const Resolver* resolver = resolverOf(spec.type)) return resolver->check(spec);
    if (!contains(spec.type)) (void)create(spec.type);  // throws, naming the known types
}

std::unique_ptr<Service> ServiceRegistry::create(const std::string& name) const {
    const auto it = factories_.find(name);
    if (it == factories_.end()) {
        std::string known;
        for (const auto& [n, f] : factories_) known += (known.empty() ? "" : ", ") + n;
        throw std::out_of_range("unknown service type '" + name + "' (known: " + (known.empty() ? "none" : known) +
                                ")");
    }
    return it->second.factory();
}

std::vector<std::string> ServiceRegistry::names() const {
    std::vector<std::string> out;
    for (const auto& [n, f] : factories_) out.push_back(n);
    return out;
}

}  // namespace sbsim::services
