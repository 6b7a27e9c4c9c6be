#!/usr/bin/env bash
# A TEST public-key infrastructure for ncbridge's DDS Security profile (security.xml): a CA,
# one identity (certificate + key) per name, the governance and a permissions document that
# grants every named identity all ncbridge topics, both signed by the CA (S/MIME, as DDS
# Security wants). Made at test or install time: private keys are never committed.
#   make-test-pki.sh OUTDIR NAME...     e.g. make-test-pki.sh /etc/ncbridge/pki services client
# Subject names are CN=<name>,O=ncbridge,C=NL (no spaces after commas: Cyclone rejects them).
set -euo pipefail
out=$1; shift
(( $# > 0 )) || { echo "usage: $0 OUTDIR NAME..." >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
cd "$out"
q() { "$@" > /dev/null 2>&1 || { echo "make-test-pki: failed: $*" >&2; exit 1; }; }

q openssl req -x509 -newkey rsa:2048 -nodes -days 30 -keyout ca_key.pem -out ca_cert.pem \
  -subj "/C=NL/O=ncbridge/CN=ncbridge test CA"
now=$(date -u +%Y-%m-%dT%H:%M:%S)
later=$(date -u -d '+30 days' +%Y-%m-%dT%H:%M:%S)
{
  echo '<?xml version="1.0" encoding="UTF-8"?>'
  echo '<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd">'
  echo '  <permissions>'
  for name in "$@"; do
    q openssl req -newkey rsa:2048 -nodes -keyout "${name}_key.pem" -out "${name}.csr" -subj "/C=NL/O=ncbridge/CN=${name}"
    q openssl x509 -req -in "${name}.csr" -CA ca_cert.pem -CAkey ca_key.pem -CAcreateserial -days 30 -out "${name}_cert.pem"
    rm -f "${name}.csr"
    cat <<XML
    <grant name="${name}">
      <subject_name>CN=${name},O=ncbridge,C=NL</subject_name>
      <validity><not_before>${now}</not_before><not_after>${later}</not_after></validity>
      <allow_rule>
        <domains><id_range><min>0</min><max>230</max></id_range></domains>
        <publish><topics><topic>ncbridge/*</topic></topics></publish>
        <subscribe><topics><topic>ncbridge/*</topic></topics></subscribe>
        <!-- A job's input goes to its owner in the owner's partition, and the statuses ending
             a job go to the workers in ncbridge.over (docs/deployment.md): a rule without
             partitions allows only the default one. -->
        <publish><topics><topic>ncbridge/*</topic></topics><partitions><partition>ncbridge.*</partition></partitions></publish>
        <subscribe><topics><topic>ncbridge/*</topic></topics><partitions><partition>ncbridge.*</partition></partitions></subscribe>
      </allow_rule>
      <default>DENY</default>
    </grant>
XML
  done
  echo '  </permissions>'
  echo '</dds>'
} > permissions.xml
q openssl smime -sign -text -in "$here/governance.xml" -out governance.p7s -signer ca_cert.pem -inkey ca_key.pem
q openssl smime -sign -text -in permissions.xml -out permissions.p7s -signer ca_cert.pem -inkey ca_key.pem
echo "make-test-pki: CA, identities ($*), signed governance and permissions in $out"
