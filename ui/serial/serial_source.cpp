#include "serial/serial_source.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QSerialPort>
#include <QSerialPortInfo>

namespace fog::serial {

namespace {

QSerialPort::Parity toQt(Parity p) {
  switch (p) {
    case Parity::kEven: return QSerialPort::EvenParity;
    case Parity::kOdd: return QSerialPort::OddParity;
    case Parity::kNone: break;
  }
  return QSerialPort::NoParity;
}

std::string text(const QString& s) { return s.toStdString(); }

}  // namespace

Status SerialSettings::validate() const {
  if (port.empty()) return invalidArgument("no serial port given (--port DEVICE; fogbench-cli ports lists them)");
  if (baudRate <= 0) return invalidArgument("the baud rate must be > 0, got " + std::to_string(baudRate));
  if (dataBits < 5 || dataBits > 8) return invalidArgument("data bits must be 5..8, got " + std::to_string(dataBits));
  if (stopBits != 1 && stopBits != 2) return invalidArgument("stop bits must be 1 or 2, got " + std::to_string(stopBits));
  return Status::ok();
}

std::string SerialSettings::summary() const {
  const char p = parity == Parity::kEven ? 'E' : parity == Parity::kOdd ? 'O' : 'N';
  return std::to_string(baudRate) + " " + std::to_string(dataBits) + p + std::to_string(stopBits);
}

Result<Parity> parseParity(const std::string& t) {
  if (t == "none") return Parity::kNone;
  if (t == "even") return Parity::kEven;
  if (t == "odd") return Parity::kOdd;
  return invalidArgument("parity must be none, even or odd, got '" + t + "'");
}

void ensureQtCore() {
  if (QCoreApplication::instance()) return;
  static int argc = 1;
  static char name[] = "fogbench";
  static char* argv[] = {name, nullptr};
  static QCoreApplication app(argc, argv);
}

std::vector<PortInfo> availablePorts() {
  std::vector<PortInfo> out;
  for (const QSerialPortInfo& p : QSerialPortInfo::availablePorts())
    out.push_back(PortInfo{text(p.portName()), text(p.systemLocation()), text(p.description()),
                           text(p.manufacturer()), text(p.serialNumber())});
  return out;
}

Result<std::unique_ptr<SerialSource>> SerialSource::open(const SerialSettings& settings) {
  FOG_RETURN_IF_ERROR(settings.validate());
  auto port = std::make_unique<QSerialPort>();
  port->setPortName(QString::fromStdString(settings.port));
  // Set before open(), which applies them at once: the line never runs at
  // QSerialPort's defaults (9600) in between.
  port->setBaudRate(settings.baudRate);
  port->setDataBits(static_cast<QSerialPort::DataBits>(settings.dataBits));
  port->setParity(toQt(settings.parity));
  port->setStopBits(settings.stopBits == 2 ? QSerialPort::TwoStop : QSerialPort::OneStop);
  port->setFlowControl(QSerialPort::NoFlowControl);
  // Read-write for the optional host-to-board commands; a port the system
  // lets us only read still records.
  bool writable = port->open(QIODevice::ReadWrite);
  if (!writable && port->error() == QSerialPort::PermissionError) {
    port->clearError();
    port->open(QIODevice::ReadOnly);
  }
  if (!port->isOpen()) {
    const bool settingsRefused = port->error() == QSerialPort::UnsupportedOperationError ||
                                 port->error() == QSerialPort::UnknownError;
    return ioError("cannot open serial port " + settings.port +
                   (settingsRefused ? " for " + settings.summary() : std::string()) + ": " +
                   text(port->errorString()));
  }
  // The driver's buffer is not cleared: whatever arrives from here on is
  // what the session stores (the decoder resynchronises on stale bytes).
  auto source = std::unique_ptr<SerialSource>(new SerialSource(std::move(port), settings));
  source->writable_ = writable;
  return source;
}

SerialSource::SerialSource(std::unique_ptr<QSerialPort> port, SerialSettings settings)
    : port_(std::move(port)), settings_(std::move(settings)) {}

SerialSource::~SerialSource() = default;

Status SerialSource::vanished(const std::string& why) {
  failed_ = ioError("serial port " + settings_.port + " vanished: " + why);
  port_->close();
  return failed_;
}

bool SerialSource::queueForDevice(std::span<const std::uint8_t> bytes) {
  if (!writable_) return false;
  std::lock_guard lock(outboxMutex_);
  // A board that never reads cannot make this grow without bound: commands
  // are a few dozen bytes per test point, and QSerialPort takes them at once.
  outbox_.insert(outbox_.end(), bytes.begin(), bytes.end());
  return true;
}

void SerialSource::writeQueued(int timeoutMs) {
  std::vector<std::uint8_t> bytes;
  {
    std::lock_guard lock(outboxMutex_);
    bytes.swap(outbox_);
  }
  if (!bytes.empty() && port_->isOpen())
    port_->write(reinterpret_cast<const char*>(bytes.data()), static_cast<qint64>(bytes.size()));
  if (port_->isOpen() && port_->bytesToWrite() > 0 && !port_->waitForBytesWritten(timeoutMs) &&
      port_->error() == QSerialPort::TimeoutError)
    port_->clearError();  // the rest goes out with the next wait
}

void SerialSource::flushToDevice(std::chrono::milliseconds timeout) {
  if (failed_.isOk() && writable_) writeQueued(static_cast<int>(timeout.count()));
}

Result<acquisition::ReadOutcome> SerialSource::read(std::vector<std::uint8_t>& out,
                                                    std::chrono::milliseconds timeout) {
  if (!failed_.isOk()) return failed_;
  if (writable_) writeQueued(0);
  if (port_->bytesAvailable() == 0 && !port_->waitForReadyRead(static_cast<int>(timeout.count()))) {
    const auto error = port_->error();
    if (error == QSerialPort::TimeoutError || error == QSerialPort::NoError) {
      port_->clearError();
      // A quiet line, unless the device node itself has gone (some drivers
      // report an unplugged adapter only as silence).
#ifndef Q_OS_WIN
      if (!QFileInfo::exists(QString::fromStdString(settings_.port)) &&
          !QFileInfo::exists(QStringLiteral("/dev/") + QString::fromStdString(settings_.port)))
        return vanished("the device no longer exists");
#endif
      return acquisition::ReadOutcome{0, false};
    }
    return vanished(text(port_->errorString()));
  }
  const QByteArray data = port_->readAll();
  if (data.isEmpty() && port_->error() != QSerialPort::NoError) return vanished(text(port_->errorString()));
  out.insert(out.end(), data.begin(), data.end());
  return acquisition::ReadOutcome{static_cast<std::size_t>(data.size()), false};
}

std::string SerialSource::description() const { return "serial " + settings_.port + " at " + settings_.summary(); }

}  // namespace fog::serial
