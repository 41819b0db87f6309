@echo off
rem D-former for Adobe Illustrator: installs the panel for this user on Windows.
rem Double-click this file. It copies com.dformer.panel into %APPDATA%\Adobe\CEP\extensions and
rem sets PlayerDebugMode = "1" (a string) under HKEY_CURRENT_USER\Software\Adobe\CSXS.8 to CSXS.12,
rem which lets Illustrator load a panel that is not signed by Adobe's ZXPSignCmd. Nothing else is changed.
setlocal
set "ID=com.dformer.panel"
set "SRC=%~dp0%ID%"
set "DEST=%APPDATA%\Adobe\CEP\extensions\%ID%"
if not exist "%SRC%\CSXS\manifest.xml" (
  echo D-former: the folder %ID% is not next to this installer ^(%~dp0^).
  echo Unzip the whole D-former Illustrator zip first, then double-click install-windows.cmd inside it.
  goto :failed
)
if exist "%DEST%" rmdir /s /q "%DEST%"
xcopy "%SRC%" "%DEST%\" /e /i /q /y >nul
if errorlevel 1 goto :failed
for %%V in (8 9 10 11 12) do (
  reg add "HKCU\Software\Adobe\CSXS.%%V" /v PlayerDebugMode /t REG_SZ /d 1 /f >nul
  if errorlevel 1 goto :failed
)
echo D-former is installed in:
echo   %DEST%
echo Restart Illustrator, then open Window ^> Extensions (Legacy) ^> D-former.
if not defined DFORMER_NO_PAUSE pause
exit /b 0
:failed
echo D-former was not installed.
if not defined DFORMER_NO_PAUSE pause
exit /b 1
