#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/services/ServiceTraits.h"

namespace sbsim::services {

class Service;
struct ServiceSpec;

/// Service types by name, like OMNeT++'s module registry: a services file names a type, the
/// registry makes an instance. Types register themselves with SBSIM_REGISTER_SERVICE next to the
/// class, in the program or in a plugin loaded with --plugin.
class SBSIM_API ServiceRegistry {
public:
    using Factory = std::function<std::unique_ptr<Service>()>;
    /// Makes the services of a family of types named by a prefix (Artery-style "python:warner.py:Warner"),
    /// which need their <service> entry (a file relative to the services file) to be found.
    struct Resolver {
        /// Throws ServicesConfigError naming the entry's file and line if the type cannot be made.
        std::function<void(const ServiceSpec&)> check;
        std::function<std::unique_ptr<Service>(const ServiceSpec&)> create;
        /// What the entry's service provides (it may have to load it: throws as check does).
        std::function<ServiceTraits(const ServiceSpec&)> traits;
        /// The files the entry's service is read from, known without loading it (the run's inputs).
        std::function<std::vector<std::filesystem::path>(const ServiceSpec&)> files;
    };

    static ServiceRegistry& instance();

    /// Registers `factory` under `name`. A second type with the same name is kept out and noted:
    /// registration runs while a library loads, where an exception would abort the program, so
    /// the loader asks takeConflict() afterwards.
    void add(const std::string& name, Factory factory);
    /// The same, with what the type provides.
    void add(const std::string& name, Factory factory, ServiceTraits traits);
    /// The first name registered twice since the last call, if any.
    std::optional<std::string> takeConflict();
    /// Types starting with `prefix` are made by `resolver` (one per prefix; a second is a conflict).
    void addResolver(const std::string& prefix, Resolver resolver);
    /// A registered type, or one a resolver's prefix names.
    bool contains(const std::string& name) const { return factories_.count(name) != 0 || resolverOf(name); }
    /// Throws std::out_of_range naming the known types if `name` is unknown.
    std::unique_ptr<Service> create(const std::string& name) const;
    /// The service of `spec`'s type: a resolver's for its prefix, else create(spec.type).
    std::unique_ptr<Service> create(const ServiceSpec& spec) const;
    /// Before the run: throws as create(spec) would for a type nobody can make (a resolver's
    /// check: a missing file or class, ServicesConfigError).
    void check(const ServiceSpec& spec) const;
    std::vector<std::string> names() const;
    /// What type `name` provides (nothing for an unknown type, or one a resolver makes).
    ServiceTraits traits(const std::string& name) const;
    /// What `spec`'s service provides: its resolver's answer for the entry, else traits(spec.type).
    /// A resolver may load the service to answer (throwing as check(spec) does).
    ServiceTraits traits(const ServiceSpec& spec) const;
    /// The files `spec`'s service is read from besides the services file (a resolver's; none for a
    /// registered type): the run counts them as inputs, so no output may overwrite them.
    std::vector<std::filesystem::path> files(const ServiceSpec& spec) const;

private:
    const Resolver* resolverOf(const std::string& type) const;

    struct Entry {
        Factory factory;
        ServiceTraits traits;
    };
    std::map<std::string, Entry> factories_;
    std::map<std::string, Resolver> resolvers_;
    std::optional<std::string> conflict_;
};

namespace detail {
struct SBSIM_API ServiceRegistration {
    ServiceRegistration(const std::string& name, ServiceRegistry::Factory factory) {
        ServiceRegistry::instance().add(name, std::move(factory));
    }
    ServiceRegistration(const std::string& name, ServiceRegistry::Factory factory, ServiceTraits traits) {
        ServiceRegistry::instance().add(name, std::move(factory), traits);
    }
};

/// `Class::kProvides` if the class declares it, else nothing provided.
template <class Class>
constexpr ServiceTraits traitsOf() {
    if constexpr (requires { Class::kProvides; }) {
        return Class::kProvides;
    } else {
        return {};
    }
}
}  // namespace detail

}  // namespace sbsim::services

/// Registers service class `Class` under its own name (OMNeT++'s Define_Module).
#define SBSIM_REGISTER_SERVICE(Class) SBSIM_REGISTER_SERVICE_AS(Class, #Class)
/// Registers service class `Class` under `name`.
#define SBSIM_REGISTER_SERVICE_AS(Class, name)                                                       \
    static const ::sbsim::services::detail::ServiceRegistration sbsimServiceRegistration_##Class {   \
        name, [] { return std::make_unique<Class>(); }, ::sbsim::services::detail::traitsOf<Class>() \
    }
