// The OpenSSL functions comms uses, each forwarding to libssl.so.3's own (OpenSslLibrary.h).
// (hsmu_comms and hsmu_controller). One line per function, with OpenSSL 3's signature from its headers (a mismatch fails the
// compile: the headers declare the same names). Hidden: a shared object linking comms (the
// Python module) exports none of them, so they never stand in for another user's OpenSSL.

#include "comms/tls/OpenSslLibrary.h"

#include <openssl/bio.h>
#include <openssl/err.h>
#include <openssl/evp.h>
#include <openssl/pem.h>
#include <openssl/ssl.h>
#include <openssl/x509v3.h>

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>

namespace hsmu::comms {

namespace {

constexpr const char* kLibrary = "libssl.so.3"; // brings libcrypto.so.3 with it

struct Loaded {
    void* handle = nullptr;
    std::string error;
    Loaded() {
        handle = dlopen(kLibrary, RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* why = dlerror();
            error = std::string("tls:// links need OpenSSL 3 (") + kLibrary +
                    "), which cannot be loaded: " + (why ? why : "unknown reason");
        }
    }
};

const Loaded& loaded() {
    static const Loaded library; // thread-safe, once
    return library;
}

/// The loaded library's function `name` (its dependencies, libcrypto, searched too). Only
/// reached once loadOpenSsl() succeeded (every OpenSSL object comes from a context that
/// makeTlsContext made after loading); a missing symbol is a broken installation.
void* openSslSymbol(const char* name) {
    void* fn = loaded().handle ? dlsym(loaded().handle, name) : nullptr;
    if (!fn) {
        std::fprintf(stderr, "hsmu: OpenSSL function %s not found (%s): %s\n", name, kLibrary,
                     loaded().handle ? dlerror() : loaded().error.c_str());
        std::abort();
    }
    return fn;
}

} // namespace

bool loadOpenSsl(std::string& error) {
    if (loaded().handle)
        return true;
    error = loaded().error;
    return false;
}

} // namespace hsmu::comms

#define HSMU_OPENSSL(ret, name, params, args)                                                  \
    extern "C" __attribute__((visibility("hidden"))) ret name params {                        \
        static const auto real =                                                               \
            reinterpret_cast<decltype(&::name)>(hsmu::comms::openSslSymbol(#name));            \
        return real args;                                                                      \
    }

// clang-format off
HSMU_OPENSSL(long, BIO_ctrl, (BIO *bp, int cmd, long larg, void *parg), (bp, cmd, larg, parg))
HSMU_OPENSSL(size_t, BIO_ctrl_pending, (BIO *b), (b))
HSMU_OPENSSL(int, BIO_free, (BIO *a), (a))
HSMU_OPENSSL(BIO *, BIO_new_file, (const char *filename, const char *mode), (filename, mode))
HSMU_OPENSSL(int, BIO_new_bio_pair, (BIO **bio1, size_t writebuf1, BIO **bio2, size_t writebuf2), (bio1, writebuf1, bio2, writebuf2))
HSMU_OPENSSL(int, BIO_read, (BIO *b, void *data, int dlen), (b, data, dlen))
HSMU_OPENSSL(int, BIO_write, (BIO *b, const void *data, int dlen), (b, data, dlen))
HSMU_OPENSSL(void, ERR_clear_error, (), ())
HSMU_OPENSSL(unsigned long, ERR_get_error, (), ())
HSMU_OPENSSL(const char *, ERR_reason_error_string, (unsigned long e), (e))
HSMU_OPENSSL(const EVP_MD *, EVP_sha256, (), ())
HSMU_OPENSSL(X509_CRL *, PEM_read_bio_X509_CRL, (BIO *out, X509_CRL **x, pem_password_cb *cb, void *u), (out, x, cb, u))
HSMU_OPENSSL(int, SSL_CTX_check_private_key, (const SSL_CTX *ctx), (ctx))
HSMU_OPENSSL(long, SSL_CTX_ctrl, (SSL_CTX *ctx, int cmd, long larg, void *parg), (ctx, cmd, larg, parg))
HSMU_OPENSSL(void, SSL_CTX_free, (SSL_CTX * a0), (a0))
HSMU_OPENSSL(void *, SSL_CTX_get_default_passwd_cb_userdata, (SSL_CTX *ctx), (ctx))
HSMU_OPENSSL(X509_STORE *, SSL_CTX_get_cert_store, (const SSL_CTX *ctx), (ctx))
HSMU_OPENSSL(void *, SSL_CTX_get_ex_data, (const SSL_CTX *ssl, int idx), (ssl, idx))
HSMU_OPENSSL(SSL_verify_cb, SSL_CTX_get_verify_callback, (const SSL_CTX *ctx), (ctx))
HSMU_OPENSSL(int, SSL_CTX_load_verify_locations, (SSL_CTX *ctx, const char *CAfile, const char *CApath), (ctx, CAfile, CApath))
HSMU_OPENSSL(SSL_CTX *, SSL_CTX_new, (const SSL_METHOD *meth), (meth))
HSMU_OPENSSL(void, SSL_CTX_set_default_passwd_cb_userdata, (SSL_CTX *ctx, void *u), (ctx, u))
HSMU_OPENSSL(int, SSL_CTX_set_ex_data, (SSL_CTX *ssl, int idx, void *data), (ssl, idx, data))
HSMU_OPENSSL(int, SSL_CTX_set_num_tickets, (SSL_CTX *ctx, size_t num_tickets), (ctx, num_tickets))
HSMU_OPENSSL(uint64_t, SSL_CTX_set_options, (SSL_CTX *ctx, uint64_t op), (ctx, op))
HSMU_OPENSSL(void, SSL_CTX_set_verify, (SSL_CTX *ctx, int mode, SSL_verify_cb callback), (ctx, mode, callback))
HSMU_OPENSSL(int, SSL_CTX_use_PrivateKey_file, (SSL_CTX *ctx, const char *file, int type), (ctx, file, type))
HSMU_OPENSSL(int, SSL_CTX_use_certificate_chain_file, (SSL_CTX *ctx, const char *file), (ctx, file))
HSMU_OPENSSL(int, SSL_accept, (SSL *ssl), (ssl))
HSMU_OPENSSL(int, SSL_connect, (SSL *ssl), (ssl))
HSMU_OPENSSL(long, SSL_ctrl, (SSL *ssl, int cmd, long larg, void *parg), (ssl, cmd, larg, parg))
HSMU_OPENSSL(void, SSL_free, (SSL *ssl), (ssl))
HSMU_OPENSSL(X509 *, SSL_get1_peer_certificate, (const SSL *s), (s))
HSMU_OPENSSL(int, SSL_get_error, (const SSL *s, int ret_code), (s, ret_code))
HSMU_OPENSSL(void *, SSL_get_ex_data, (const SSL *ssl, int idx), (ssl, idx))
HSMU_OPENSSL(int, SSL_get_ex_data_X509_STORE_CTX_idx, (), ())
HSMU_OPENSSL(int, SSL_get_shutdown, (const SSL *ssl), (ssl))
HSMU_OPENSSL(int, SSL_get_verify_mode, (const SSL *s), (s))
HSMU_OPENSSL(SSL *, SSL_new, (SSL_CTX *ctx), (ctx))
HSMU_OPENSSL(int, SSL_read, (SSL *ssl, void *buf, int num), (ssl, buf, num))
HSMU_OPENSSL(void, SSL_set_bio, (SSL *s, BIO *rbio, BIO *wbio), (s, rbio, wbio))
HSMU_OPENSSL(int, SSL_set_ex_data, (SSL *ssl, int idx, void *data), (ssl, idx, data))
HSMU_OPENSSL(void, SSL_set_verify, (SSL *s, int mode, SSL_verify_cb callback), (s, mode, callback))
HSMU_OPENSSL(int, SSL_write, (SSL *ssl, const void *buf, int num), (ssl, buf, num))
HSMU_OPENSSL(const SSL_METHOD *, TLS_client_method, (), ())
HSMU_OPENSSL(const SSL_METHOD *, TLS_method, (), ())
HSMU_OPENSSL(const SSL_METHOD *, TLS_server_method, (), ())
HSMU_OPENSSL(X509 *, X509_STORE_CTX_get_current_cert, (const X509_STORE_CTX *ctx), (ctx))
HSMU_OPENSSL(int, X509_STORE_CTX_get_error, (const X509_STORE_CTX *ctx), (ctx))
HSMU_OPENSSL(int, X509_STORE_CTX_get_error_depth, (const X509_STORE_CTX *ctx), (ctx))
HSMU_OPENSSL(void *, X509_STORE_CTX_get_ex_data, (const X509_STORE_CTX *ctx, int idx), (ctx, idx))
HSMU_OPENSSL(void, X509_STORE_CTX_set_error, (X509_STORE_CTX *ctx, int s), (ctx, s))
HSMU_OPENSSL(int, X509_STORE_add_crl, (X509_STORE *ctx, X509_CRL *x), (ctx, x))
HSMU_OPENSSL(int, X509_STORE_set_flags, (X509_STORE *ctx, unsigned long flags), (ctx, flags))
HSMU_OPENSSL(void, X509_free, (X509 *a), (a))
HSMU_OPENSSL(void, X509_CRL_free, (X509_CRL *a), (a))
HSMU_OPENSSL(int, X509_check_host, (X509 *x, const char *chk, size_t chklen, unsigned int flags, char **peername), (x, chk, chklen, flags, peername))
HSMU_OPENSSL(int, X509_check_ip_asc, (X509 *x, const char *ipasc, unsigned int flags), (x, ipasc, flags))
HSMU_OPENSSL(int, X509_cmp_current_time, (const ASN1_TIME *s), (s))
HSMU_OPENSSL(int, X509_digest, (const X509 *data, const EVP_MD *type, unsigned char *md, unsigned int *len), (data, type, md, len))
HSMU_OPENSSL(const ASN1_TIME *, X509_get0_notAfter, (const X509 *x), (x))
HSMU_OPENSSL(const ASN1_TIME *, X509_get0_notBefore, (const X509 *x), (x))
HSMU_OPENSSL(const char *, X509_verify_cert_error_string, (long n), (n))
// clang-format on
