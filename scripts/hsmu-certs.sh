#!/usr/bin/env bash
# hsmu-certs.sh: the certificates of tls:// links (docs/security.md, "Two labs over TLS"),
# with the openssl command line (OpenSSL 3).
#
#   hsmu-certs.sh init-ca DIR
#       a lab CA in DIR: ca.pem (give it to every end), ca.key (mode 0600, keep it offline),
#       and the bookkeeping of `openssl ca` (index.txt, serial, openssl.cnf).
#   hsmu-certs.sh issue NAME --ca DIR [--ip ADDR]... [--dns HOST]... [--out DIR2]
#                            [--days N | --not-before YYMMDDHHMMSSZ --not-after YYMMDDHHMMSSZ]
#       NAME.pem and NAME.key (0600) in DIR2 (default: the current folder), signed by the CA
#       in DIR, valid N days (default 825) or over the window given (a window in the past
#       makes an expired certificate, for tests). A controller's certificate names the
#       addresses the console dials (--ip / --dns: subjectAltName, checked by the console);
#       a console's needs none. Keys are ECDSA P-256.
#   hsmu-certs.sh fingerprint FILE
#       the certificate's SHA-256 fingerprint (64 hex digits): a pin, or a line of a revoked
#       list (hsmu-controller --tls-pins / --tls-revoked; the console's "pins").
#   hsmu-certs.sh revoke FILE --ca DIR [--crl-days N]
#       marks the certificate FILE (issued by the CA in DIR) revoked in the CA's index.txt and
#       writes DIR/crl.pem, the CA's certificate revocation list, valid N days (default 30):
#       give it to the controllers (hsmu-controller --tls-crl, the console's "crl") and send
#       them SIGHUP.
#   hsmu-certs.sh crl --ca DIR [--crl-days N]
#       writes DIR/crl.pem again (the same revocations, a new validity): before it expires.
#
# Every file is written with umask 077 (keys must stay private: hsmu refuses a key file that
# others can read).
set -euo pipefail
umask 077

die() { echo "hsmu-certs.sh: $*" >&2; exit 2; }
usage() { sed -n '2,28p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }

init_ca() {
  local dir="${1:-}"
  [ -n "$dir" ] || usage
  [ ! -e "$dir/ca.key" ] || die "$dir/ca.key exists: one CA per folder"
  mkdir -p "$dir"
  : > "$dir/index.txt"
  echo 1000 > "$dir/serial"
  cat > "$dir/openssl.cnf" <<CNF
[ca]
default_ca = hsmu_ca
[hsmu_ca]
dir = $(cd "$dir" && pwd)
database = \$dir/index.txt
serial = \$dir/serial
new_certs_dir = \$dir
certificate = \$dir/ca.pem
private_key = \$dir/ca.key
default_md = sha256
policy = hsmu_policy
unique_subject = no
copy_extensions = none
[hsmu_policy]
commonName = supplied
organizationName = optional
CNF
  openssl req -x509 -newkey ec -pkeyopt ec_paramgen_curve:P-256 -nodes -sha256 -days 3650 \
    -subj "/O=HSMU lab/CN=HSMU lab CA $(basename "$dir")" \
    -addext "basicConstraints=critical,CA:TRUE" -addext "keyUsage=critical,keyCertSign,cRLSign" \
    -keyout "$dir/ca.key" -out "$dir/ca.pem" 2>/dev/null
  chmod 644 "$dir/ca.pem"
  echo "hsmu-certs.sh: CA in $dir (give ca.pem to every end; keep ca.key offline)"
}

issue() {
  local name="${1:-}"; shift || true
  [ -n "$name" ] && [[ "$name" != -* ]] || usage
  local ca="" out="." days=825 nb="" na="" san=()
  while [ $# -gt 0 ]; do
    case "$1" in
      --ca) ca="${2:?--ca DIR}"; shift 2 ;;
      --ip) san+=("IP:${2:?--ip ADDR}"); shift 2 ;;
      --dns) san+=("DNS:${2:?--dns HOST}"); shift 2 ;;
      --out) out="${2:?--out DIR}"; shift 2 ;;
      --days) days="${2:?--days N}"; shift 2 ;;
      --not-before) nb="${2:?--not-before YYMMDDHHMMSSZ}"; shift 2 ;;
      --not-after) na="${2:?--not-after YYMMDDHHMMSSZ}"; shift 2 ;;
      *) die "issue: unknown option $1" ;;
    esac
  done
  [ -f "$ca/ca.key" ] && [ -f "$ca/openssl.cnf" ] || die "issue: --ca DIR must be a folder made by init-ca"
  { [ -z "$nb" ] && [ -z "$na" ]; } || { [ -n "$nb" ] && [ -n "$na" ]; } ||
    die "issue: --not-before and --not-after go together"
  mkdir -p "$out"
  local ext; ext="$(mktemp)"
  trap 'rm -f "$ext" "$out/$name.csr"' RETURN
  {
    echo "[leaf]"
    echo "basicConstraints=critical,CA:FALSE"
    echo "keyUsage=critical,digitalSignature"
    echo "extendedKeyUsage=serverAuth,clientAuth"
    if [ ${#san[@]} -gt 0 ]; then (IFS=,; echo "subjectAltName=${san[*]}"); fi
  } > "$ext"
  openssl req -new -newkey ec -pkeyopt ec_paramgen_curve:P-256 -nodes -sha256 \
    -subj "/O=HSMU lab/CN=$name" -keyout "$out/$name.key" -out "$out/$name.csr" 2>/dev/null
  local window=(-days "$days")
  [ -z "$nb" ] || window=(-startdate "$nb" -enddate "$na")
  openssl ca -batch -notext -config "$ca/openssl.cnf" -extfile "$ext" -extensions leaf \
    "${window[@]}" -in "$out/$name.csr" -out "$out/$name.pem" 2>/dev/null ||
    die "issue: openssl ca failed (run it by hand: openssl ca -config $ca/openssl.cnf ...)"
  chmod 644 "$out/$name.pem"
  echo "hsmu-certs.sh: $out/$name.pem and $out/$name.key (sha256 $(fingerprint "$out/$name.pem"))"
}

fingerprint() {
  local file="${1:-}"
  [ -f "$file" ] || die "fingerprint: no such certificate: $file"
  openssl x509 -in "$file" -noout -fingerprint -sha256 | sed 's/^.*=//; s/://g' | tr 'A-F' 'a-f'
}

# crl DIR DAYS: DIR/crl.pem from the CA's index.txt (PEM, signed by the CA, mode 0644).
make_crl() {
  local ca="$1" days="$2"
  [[ "$days" =~ ^[1-9][0-9]*$ ]] || die "--crl-days: expected a whole number of days >= 1, found '$days'"
  openssl ca -batch -config "$ca/openssl.cnf" -gencrl -crldays "$days" -md sha256 \
    -out "$ca/crl.pem.tmp" 2>/dev/null || die "openssl ca -gencrl failed (run it by hand: openssl ca -config $ca/openssl.cnf -gencrl ...)"
  chmod 644 "$ca/crl.pem.tmp"
  mv "$ca/crl.pem.tmp" "$ca/crl.pem"
  echo "hsmu-certs.sh: $ca/crl.pem ($(grep -c '^R' "$ca/index.txt" || true) revoked, valid $days days)"
}

ca_options() { # sets ca and days from --ca DIR [--crl-days N]
  ca="" days=30
  while [ $# -gt 0 ]; do
    case "$1" in
      --ca) ca="${2:?--ca DIR}"; shift 2 ;;
      --crl-days) days="${2:?--crl-days N}"; shift 2 ;;
      *) die "unknown option $1" ;;
    esac
  done
  [ -f "$ca/ca.key" ] && [ -f "$ca/openssl.cnf" ] || die "--ca DIR must be a folder made by init-ca"
}

revoke() {
  local file="${1:-}"; shift || true
  [ -n "$file" ] && [[ "$file" != -* ]] || usage
  [ -f "$file" ] || die "revoke: no such certificate: $file"
  local ca days; ca_options "$@"
  openssl ca -batch -config "$ca/openssl.cnf" -revoke "$file" 2>/dev/null ||
    die "revoke: openssl ca -revoke failed ($file not issued by the CA in $ca, or already revoked)"
  make_crl "$ca" "$days"
}

crl() {
  local ca days; ca_options "$@"
  make_crl "$ca" "$days"
}

case "${1:-}" in
  init-ca) shift; init_ca "$@" ;;
  issue) shift; issue "$@" ;;
  fingerprint) shift; fingerprint "$@" ;;
  revoke) shift; revoke "$@" ;;
  crl) shift; crl "$@" ;;
  *) usage ;;
esac
