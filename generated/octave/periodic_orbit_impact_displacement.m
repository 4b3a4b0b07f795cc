function r = periodic_orbit_impact_displacement(M, K, C, m, e, d, F0, X_b, Omega, phi)
% PERIODIC_ORBIT_IMPACT_DISPLACEMENT  Main-mass displacement X at the first impact [m], Eq. F3 (derived here, beyond the paper).
%
%   r = periodic_orbit_impact_displacement(M, K, C, m, e, d, F0, X_b, Omega, phi)
%
% Arguments (scalars or arrays of compatible sizes, SI units):
%   M: Main mass M [kg]
%   K: Main stiffness K [N/m]
%   C: Main damping C (underdamped) [N s/m]
%   m: Impact mass m [kg]
%   e: Coefficient of restitution e [1]
%   d: Total clearance d [m]
%   F0: Force amplitude F0 on the main mass [N]
%   X_b: Base-motion amplitude X_b [m]
%   Omega: Forcing frequency Ω [rad/s]
%   phi: Forcing phase at the first impact φ [rad]
%
% Returns an array of the broadcast size; NaN where the result is not real.
% X = X = - \frac{- \frac{\pi M \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\pi M \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\pi M \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\pi M \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\pi M \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\pi M \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\pi M \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\pi M \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{\pi M \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \left(- \frac{C \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{2 M} + \left(\frac{C \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M} - \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)} \cos{\left(\phi \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)} + \frac{\pi M \left(- \frac{C \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{2 M} + \left(\frac{C \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M} - \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\phi \right)} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)} + \frac{2 \Omega d m e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}}{\pi M \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} + \pi M \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} + \pi M \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) + \pi M - \frac{\pi M \left(- \frac{C \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{2 M} + \left(\frac{C \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M} - \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \frac{4 \Omega m e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}}
%
% Generated by derive/periodic_orbit.py through derive/templates/octave/kernel.m.j2.
% Do not edit by hand: change the derivation and run `python -m derive`.
% Mirrors symimpact.generated.periodic_orbit.impact_displacement; operations: 115.
  x_0 = pi*M;
  x_1 = pi./Omega;
  x_2 = 1./M;
  x_3 = C.*x_2/2;
  x_4 = exp(-x_1.*x_3);
  x_5 = C.^2;
  x_6 = sqrt(K.*x_2 - x_5./(4*M.^2));
  x_7 = x_1.*x_6;
  x_8 = sin(x_7);
  x_9 = 1./x_6;
  x_10 = x_8.*x_9;
  x_11 = x_10.*x_4;
  x_12 = cos(x_7);
  x_13 = x_10.*x_3;
  x_14 = x_4.*(x_12 + x_13);
  x_15 = x_0.*x_14;
  x_16 = x_0.*(x_12.*x_4 - x_13.*x_4);
  x_17 = x_14.*x_16;
  x_18 = -x_14.*x_3 + x_4.*(x_12.*x_3 - x_6.*x_8);
  x_19 = Omega.^2;
  x_20 = x_19.*x_5;
  x_21 = K - M.*x_19;
  x_22 = 1./(x_20 + x_21.^2);
  x_23 = x_0.*x_22;
  x_24 = F0 + K.*X_b;
  x_25 = -C.*Omega.*X_b.*x_21 + C.*Omega.*x_24;
  x_26 = sin(phi);
  x_27 = x_25.*x_26;
  x_28 = X_b.*x_20 + x_21.*x_24;
  x_29 = cos(phi);
  x_30 = x_28.*x_29;
  x_31 = x_15.*x_22;
  x_32 = x_16.*x_22;
  x_33 = x_17.*x_22;
  r = -(pi*M.*x_18.*x_22.*x_25.*x_26.*x_4.*x_8.*x_9 + pi*M.*x_18.*x_22.*x_28.*x_29.*x_4.*x_8.*x_9 + 2*Omega.*d.*m.*x_4.*x_8.*x_9 - x_23.*x_27 - x_23.*x_30 - x_27.*x_31 - x_27.*x_32 - x_27.*x_33 - x_30.*x_31 - x_30.*x_32 - x_30.*x_33)./(4*Omega.*m.*x_11 - x_0.*x_11.*x_18 + x_0 + x_15 + x_16 + x_17);
  r = r + zeros(size(M + K + C + m + e + d + F0 + X_b + Omega + phi));
  if ~isreal(r)
    r(imag(r) ~= 0) = NaN;
    r = real(r);
  end
end
